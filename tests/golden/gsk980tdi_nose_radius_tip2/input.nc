O0701 (GSK980TDi - G41 nose radius compensation in a bore, tip 2, R0.4 - setup.toml)
(Hand check, radii in X - the nose centre runs 0.4 off the contour on the left of travel - below the bore wall; the record is the imaginary tip, centre + 0.4 in +X and -Z.)
T0202
G99 G97 S800 M03
G00 X40. Z2.
(Start-up perpendicular to the chamfer - tip X40.2343 Z-0.1172.)
G41 G01 Z0 F0.1
(45-degree chamfer into the bore - the tip 0.4 x [sqrt2 - 1] or 0.1657 inside it.)
X36. Z-2.
(Z-parallel - the tip on X36 - into the inner corner with the arc - the centre line X17.6 radius meets the offset circle of radius 3.4 at Z-19.6236 - tip Z-20.0236.)
Z-20.
(G02 R3 about X18 Z-23 radius - moved by the tip vector, X36.8 Z-23.4 - ends where the circle meets the face's centre line Z-22.6 - tip X30.0472 Z-23.)
G02 X30. Z-23. R3.
(X-parallel face - the tip on Z-23 - cancelled perpendicular - tip X24.8 - then G40 to Z5.)
G01 X24.
G40 G00 Z5.
M30
