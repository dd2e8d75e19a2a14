%
O0001 (CUSTOM MACRO B: A BOLT CIRCLE BY G65, WHILE, IF, VACANT WORDS)
(Hand check - fanuc0m, G21 G17 G90, rapid 10000 mm/min.)
(Line 7 - rapid to X0 Y0 Z10, one record, call_depth 0.)
(Line 8 - G65 P9100: A4. = #1 holes, R20. = #18 radius, Z-3. = #26 depth, F200. = #9 feed.)
(In O9100 - #10 counts 0 to 3 - each hole at angle 90 x #10: X = 20 COS, Y = 20 SIN.)
G21 G17 G90 G00 X0. Y0. Z10.
G65 P9100 A4. R20. Z-3. F200.
(Holes - X20 Y0, X0 Y20, X-20 Y0, X0 Y-20 - COS 90 is 0 to the least increment - each a rapid and a feed down and a rapid up, depth 1.)
(Line 12 - after the return #10 is vacant in the main programme - level 0 - so Y#10 disappears - X5, Y stays -20.)
(Each feed down is 13 mm at F200 - 3.9 s plus the acceleration, 3.95 s.)
G00 X5. Y#10
M30
O9100
#10 = 0
WHILE [#10 LT #1] DO1
#11 = 90 * #10
G00 X[#18 * COS[#11]] Y[#18 * SIN[#11]]
G01 Z#26 F#9
G00 Z10.
#10 = #10 + 1
END1
IF [#10 EQ 4] GOTO 90
#3000 = 1 (NOT REACHED)
N90 M99
%
