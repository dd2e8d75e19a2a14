(D outside G41/G42 - modal data - the offset number the next G41/G42 uses - FANUC #4107 - docs/compensation.md.)
(Line 8 - G43 H0 D1 - no length offset - D1 kept - line 9 - G41 - still G00 - without D takes D1 - radius 5.)
(The start-up ends perpendicular to the next move - along +Y - 5 mm to its left - X5 Y0.)
(Line 10 - up to Y10 - it ends on its corner with line 11's move at the old radius 5 - X5 Y15 - 15 mm at F100 - 9 s plus 0.05 s.)
(Line 11 - D2 in compensation - its move starts on the old vector and ends on the new radius 3 - perpendicular before the G40 - X20 Y13 - 15.133 mm - 9.08 s plus 0.05 s.)
(Line 12 - G40 X30 Y0 - the cancel move ends on the programmed point.)
G90 G17 G00 X0 Y0 Z10.
G43 H0 D1 Z10.
G41 X10. Y0 F100.
G01 Y10.
D2 X20.
G40 X30. Y0
M30
