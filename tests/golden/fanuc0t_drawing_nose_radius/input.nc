O0194 (FANUC 0-T - chamfer and corner R in nose radius compensation - G42 - R0.8 - imaginary tool nose 3 - setup.toml)
(Hand check - the corner stage makes the programmed path with its chamfer and arc - compensation then offsets that path 0.8 to the right - records are the imaginary tip - the nose centre less 0.8 on X radius and on Z.)
T0101
G98 G97 S800 M03
G00 X20. Z2.
G42 G01 Z0 F100.
(X40. ,C2. - the programmed chamfer X36 Z0 to X40 Z-2 - the line z + r = 18. Offset right of the face - centre z 0.8 - and of the chamfer - z + r = 18 + 0.8 sqrt2 = 19.1314 - meet at r 18.3314 - tip X35.0627 Z0.)
X40. ,C2.
(Z-20. ,R2. - the chamfer's offset meets the Z line's - r 20.8 - at z -1.6686 - tip X40 Z-2.4686. The arc - programmed from Z-18 X40 to Z-20 X44 about Z-18 X44 - turns clockwise - the nose inside it - radius 1.2 - tip from X40 Z-18.8 to X42.4 Z-20.)
Z-20. ,R2.
(X50. - the face at z -20 - the nose centre at z -19.2 - tip Z-20 - ends perpendicular before G00 - the centre at r 25 z -19.2 - tip X48.4 Z-20.)
X50.
G40 G00 X60. Z10.
M30
