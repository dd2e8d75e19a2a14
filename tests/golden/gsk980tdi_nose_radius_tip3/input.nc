O0700 (GSK980TDi - G42 tool nose radius compensation, tip 3, R0.8 - setup.toml)
(Hand check, radii in X - the nose centre runs 0.8 off the contour on the right of travel; the record is the imaginary tip, centre + 0.8 in -X and -Z.)
T0101
G99 G97 S1000 M03
G00 X20. Z2.
(Start-up, type A - ends perpendicular to the next move - centre Z0.5657 X10.5657 - tip X19.5314 Z-0.2343.)
G42 G01 Z0 F0.1
(45-degree chamfer - the tip runs 0.8 x [sqrt2 - 1] or 0.3314 inside it - ends X30 Z-5.4686.)
X30. Z-5.
(Z-parallel - the tip on X30 - to the taper's inner corner at Z-15.6111.)
Z-15.
(Taper X15 to X20 radius over 10 - outer corner into the Z line - the offsets meet at Z-25.6111.)
X40. Z-25.
(Z-parallel - the tip on X40 - the concave arc starts tangent - centre at X20.8 radius, tip Z-30.8.)
Z-30.
(Concave G02 R5 about X25 Z-30 - the centre on radius 5 - 0.8 or 4.2 - the record's centre X48.4 Z-30.8 is the programmed one moved by the tip vector.)
G02 X50. Z-35. R5.
(X-parallel face - the tip on Z-35.)
G01 X60.
(Convex G03 R5 about X30 Z-40 radius - the centre on radius 5.8.)
G03 X70. Z-40. R5.
(Z-parallel - the tip on X70 - cancelled at the end perpendicular - tip Z-50.8 - then G40 to X100 Z-50.)
G01 Z-50.
G40 G00 X100.
M30
