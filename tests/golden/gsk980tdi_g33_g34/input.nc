(G33 tapping - help text - Z-20 at lead 1.5 from Z5 - in, M05, reverse, out, M05 - 25 mm at 1.5 x 200 = 300 mm/min is 5 s each way.)
(G34 variable lead - F2 R0.5 from Z5 to Z-20 - revolution n at lead 2 + 0.5 x [n + 0.5] - 2.25, 2.75, 3.25, ... until 25 mm.)
G97 S200 M03
G0 X0 Z5
G33 Z-20 F1.5
M03
G0 X40 Z5
G34 Z-20 F2 R0.5
G0 X60
M30
