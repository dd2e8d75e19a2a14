(D outside G41/G42 - modal data - the offset number the next G41/G42 uses - FANUC #4107 - docs/compensation.md.)
(Line 8 - G43 H0 D1 - no length offset - D1 kept - line 9 - G41 - still G00 - without D takes D1 - radius 5.)
(The start-up ends perpendicular to the next move - along +Y - 5 mm to its left - X5 Y0.)
(Line 10 - up to Y10 - the nose centre X5 Y10 - line 11 - D2 in compensation - radius 3 from this block on.)
(The path so far ends perpendicular at X5 Y10 - the move to X20 Y10 starts anew - its end 3 mm to its left - X20 Y13.)
(Line 12 - G40 X30 Y0 - the cancel move ends on the programmed point.)
G90 G17 G00 X0 Y0 Z10.
G43 H0 D1 Z10.
G41 X10. Y0 F100.
G01 Y10.
D2 X20.
G40 X30. Y0
M30
