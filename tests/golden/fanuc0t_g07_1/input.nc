O0071 (FANUC 0-T - G07.1 cylindrical interpolation - a groove milled on a cylinder of radius 20 with the C axis)
(Hand check - FANUC 0i-T manual - between G07.1 C20. and G07.1 C0 the programme is written on the cylinder unrolled - Z and C in degrees - 1 degree is 20 x pi/180 = 0.34907 mm of surface; F is the speed along the unrolled path. G19 - C parallel to Y - comes first in the plane.)
G98 G00 X44. Z5. C0
G19
G07.1 C20.
(Into the cylinder - X36. - 4 mm - 2.4 s + 0.05.)
G01 X36. F100.
(Z-10. C30. - 15 mm of Z with 10.472 mm of surface - 18.294 mm - 10.976 s + 0.05; Z at 15/10.976 = 81.995 mm/min, C at 30/10.976 = 163.99 deg/min.)
Z-10. C30.
(G02 Z-20. C60. R10. - on the unrolled plane - C first - from s 10.472 z -10 to s 20.944 z -20 - clockwise about s 10.944 z -19.989 - chords within 0.001 mm, each end 10 mm from the centre.)
G02 Z-20. C60. R10.
(C90. - 30 degrees alone - 10.472 mm - 6.283 s - at 286.479 deg/min.)
G01 C90.
X44.
(G07.1 C0 - the mode ends with the machine at C90.)
G07.1 C0
G18 G00 Z20.
M30
