%
O0001 (MACRO B CONSTRUCTS ONE BY ONE - HAND CHECKED)
(fanuc0m, G21 G17 G90. The first rapid to X0 Y0 Z10 is line 7.)
(A. Vacant - #5 never set - Y#5 disappears, Z[#5+2] is Z2 - line 9 goes to X1 Y0 Z2.)
(B. Rounding on negatives - FIX[-1.7] = -1, FUP[-1.2] = -2, ROUND[-2.5] = -3 - line 12 to X-1 Y-2 Z-3.)
(Inside an address ROUND rounds to the least increment - FANUC's example - so line 13's Z[ROUND[-2.5]] is Z-2.5; line 14 back to Z10.)
G21 G17 G90 G00 X0. Y0. Z10.
#1 = 1
G00 X#1 Y#5 Z[#5+2]
#2 = FIX[-1.7]
#6 = ROUND[-2.5]
G00 X#2 Y[FUP[-1.2]] Z#6
G00 Z[ROUND[-2.5]]
G00 Z10.
(C. WHILE nesting - DO1 twice holding DO2 three times - X counts 1 to 6 on line 22, then Y5 on line 27.)
#1 = 0
#3 = 0
WHILE [#1 LT 2] DO1
#2 = 0
WHILE [#2 LT 3] DO2
#3 = #3 + 1
G00 X#3
#2 = #2 + 1
END2
#1 = #1 + 1
END1
G00 Y5.
(D. Computed GOTO - #4 = 3 - GOTO [#4*10] goes to N30 - N20's X99 is passed over - line 32 to X7, n 30.)
#4 = 3
GOTO [#4 * 10]
N20 G00 X99.
N30 G00 X7.
(E. G65 locals against M98 - #1 = 5 here - G65 A8. gives O0100 its own #1 = 8 - X8 on line 52, depth 1.)
(Back here #1 is 5 again - X5 on line 37 - M98 P200 shares #1 - Y5 on line 56 - and sets #1 = 6 - X6 on line 39.)
#1 = 5
G65 P100 A8.
G00 X#1
M98 P200
G00 X#1
(F. G66 after each move - O0300 feeds Z down to Z#26 = -1 and back - after X10 on line 42 and X12 on line 43 - lines 60 and 61 at depth 1 - not after G67's X14 on line 45.)
G66 P300 Z-1.
G00 X10.
X12.
G67
X14.
(G. #5001 and #5041 - after G81 at X20 Y20 from Z10 with G98 the tool is at X20 Y20 Z10 - line 49 goes to X[20+1] Y#5043 - the Z, 10 - so X21 Y10.)
G98 G81 X20. Y20. Z-2. R1. F100.
G80
G00 X[#5001 + 1] Y#5043
M30
O0100
G00 X#1
#1 = 99
M99
O0200
G00 Y#1
#1 = 6
M99
O0300
G01 Z#26 F200.
G00 Z10.
M99
%
