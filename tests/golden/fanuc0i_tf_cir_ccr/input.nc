(FANUC 0i-TF - 3403#5 CIR = 0 and 3405#4 CCR = 1 - docs/profiles.md.)
(Line 9 - G02 with neither R nor I K - CIR = 0 - a straight move to X50 Z-5 - warning NCS-W38.)
(From X40 Z2 - 5 mm in X as a radius and 7 in Z - 8.602 mm at F100 - 5.161 s plus 0.05 s.)
(Line 10 - A45 without the comma - the line at 45 degrees from +Z - X60 gives 5 mm up - so Z0 - 7.071 mm - 4.243 s plus 0.05 s.)
(Line 11 - C2 without the comma on a move along -Z - a 45 degree chamfer to the next X move - as I did.)
(The Z move ends 2 mm short at Z-18 - 18 mm - then the chamfer to X64 Z-20 - 2.828 mm - then X70 - 3 mm as a radius.)
(Line 13 - R-3 - a corner arc of radius 3 to the next move - toward -Z by its sign - the X move ends at X74 - then the arc to X80 Z-23 - then Z-40.)
G98 G00 X40. Z2.
G02 X50. Z-5. F100.
G01 X60. A45.
G01 Z-20. C2.
X70.
G01 X80. R-3.
Z-40.
M30
