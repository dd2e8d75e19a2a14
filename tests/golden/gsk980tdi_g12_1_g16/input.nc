O0124 (GSK980TDi - G12.1 with G16 - polar coordinate programming in the polar interpolation plane)
(Hand check - help text G12.1/13.1 - in the plane G15 writes X and C as Cartesian, G16 writes X the radius and C the angle in degrees; the move itself is straight in the plane, as G01 is.)
G98 G00 X40 Z2 C0
G01 Z-2 F100
G12.1
G16
(X10. C0 - radius 10 at 0 degrees - the point x 10, c 0 - a radial feed from X40 to X20 - 10 mm - 3 s.)
G01 X10. C0 F200
(C90. - radius 10 at 90 degrees - the point x 0, c 10 - straight there in the plane - 14.142 mm - 4.243 s; the machine's radius dips to 7.071 at C45 half-way, and ends at X20 C90.)
C90.
G15
(G13.1 - the machine at X20 and C90.)
G13.1
G00 Z10.
M30
