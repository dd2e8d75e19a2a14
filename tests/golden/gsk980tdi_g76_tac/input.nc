(TAC p139 example - G76 P020560 Q150 R0.1 / G76 X60.64 Z-62 P3680 Q1800 F6 - from X70 Z5.)
(Hand check - k 3.68, first depth 1.8, dmin 0.15, allowance 0.1, m 2, pull-out r 05 = 0.5 x 6 = 3 mm, a 60.)
(Depths 1.8, 1.8 sqrt2 = 2.546, 1.8 sqrt3 = 3.118, then 3.58 = k - d since 1.8 sqrt4 = 3.6 passes it, then 3.68 twice.)
(Pass X = 60.64 + 2 x [3.68 - depth] - 64.4, 62.909, 61.765, 60.84, 60.64, 60.64.)
(Pass start Z = 5 + [3.68 - depth] x tan 30 - 6.085, 5.655, 5.325, 5.058, 5, 5 - the passes follow the flank on the start's side, the full-depth ones at the programmed Z.)
(The pull-out 3 mm at 45 degrees is cut to the retract distance - radius 2.8 on the first pass.)
G97 S500 M03
G0 X70 Z5
G76 P020560 Q150 R0.1
G76 X60.64 Z-62 P3680 Q1800 F6
M30
