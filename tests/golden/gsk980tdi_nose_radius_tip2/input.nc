O0701 (GSK980TDi - G41 nose radius compensation in a bore, tip 2, R0.4 - setup.toml)
(Hand check, radii in X - the nose centre runs 0.4 off the contour on the left of travel - below the bore wall; the record is the imaginary tip, centre + 0.4 in +X and -Z.)
T0202
G99 G97 S800 M03
G00 X40. Z2.
(Start-up perpendicular to the chamfer - tip X40.2343 Z-0.1172.)
G41 G01 Z0 F0.1
(45-degree chamfer into the bore - the tip 0.4 x [sqrt2 - 1] or 0.1657 inside it.)
X36. Z-2.
(Z-parallel - the tip on X36 - into the taper's inner corner - the centre line X17.6 radius meets the taper's offset at Z-9.9505 - tip Z-10.3508.)
Z-10.
(Taper X18 to X16 radius over 8 - outer corner into the Z line - the offsets meet at centre Z-17.9508 - tip X32 Z-18.3508.)
X32. Z-18.
(Z-parallel - the tip on X32 - the concave arc starts tangent - tip Z-22.4.)
Z-22.
(Concave G03 R3 about X13 Z-22 radius - the centre on radius 2.6 - record centre X26.8 Z-22.4 - ends at tip X26.8 Z-25.)
G03 X26. Z-25. R3.
(Outer 90-degree corner after an arc - a straight move to where the offsets meet - tip X26 Z-25 - then Z-parallel on X26.)
G01 Z-30.
(Inner corner into the convex G02 R3 about X13 Z-33 - the centre line X12.6 meets the radius-3.4 circle at Z-29.6236 - tip Z-30.0236.)
G02 X20. Z-33. R3.
(Inner corner into the face - the circle meets the face's centre line Z-32.6 - tip X20.0472 Z-33 - X-parallel on Z-33 - cancelled perpendicular - tip X16.8 - then G40 to Z5.)
G01 X16.
G40 G00 Z5.
M30
