(FANUC 0-M with the 4th axis A - the setup declares it - degrees - G91 indexing as the z64 bolt circle does.)
(Line 8 - A0. where it stands: nothing turns. Line 9 - G91 A45. turns A alone at its rapid rate - 10800 deg/min by default - 45 deg in 0.25 s plus 0.1 s to accelerate - 0.35 s.)
(Lines 10-11 - the same again to A90 and A135 - line 12 - G90 A0. back - 135 deg - 0.75 + 0.1 = 0.85 s.)
(Line 13 - G01 X30. A90. F600. - 30 mm and 90 deg together - the move's length counts both - 94.87 - the X move at 600 x 30 / 94.87 = 189.74 mm/min and A at 600 x 90 / 94.87 = 569.21 deg/min - same time 9.487 s plus 0.05 s.)
(Line 14 - G00 X0 A0 - X 30 mm at 15000 mm/min - 0.12 + 0.1 = 0.22 s - A 90 deg at 10800 deg/min - 0.5 + 0.1 = 0.6 s - the turn takes 0.38 s more.)
(Line 15 - A1000 without a decimal point is 1.000 deg - least input increments as lengths - a short turn - 2 x sqrt[1 / 1800] = 0.047 s.)
G21 G17 G90 G00 X0 Y0 Z10.
A0.
G91 A45.
A45.
A45.
G90 A0.
G01 X30. A90. F600.
G00 X0 A0
A1000
M30
