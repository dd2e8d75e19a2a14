(Stored stroke check 2 - G22 X Y Z the upper limits - I J K the lower - machine coordinates - the tool may not enter the box - docs/commands/g22_g23.md.)
(Line 5 - the box X-20..20 Y-20..20 Z-10..10 - the tool at Z50 stands outside it. Line 6 - over it to X50 - line 7 - down to Z5 beside it.)
(Line 8 - G23 ends the check - line 9 - G01 X-50. passes through the box - allowed. Line 10 - back to X50 - line 11 - G22 again.)
G21 G90 G00 X0 Y0 Z50.
G22 X20. Y20. Z10. I-20. J-20. K-10.
G00 X50. Y0
G00 Z5.
G23
G01 X-50. F500.
G00 X50.
G22 X20. Y20. Z10. I-20. J-20. K-10.
(Line 13 - G01 X-50. would cross the box at Z5 - alarm - the move is not made.)
G01 X-50.
M30
