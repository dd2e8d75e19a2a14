O0501 (GSK980TDi - G05/G05.1 three-point arcs, G6.2/G6.3 ellipses, G7.2/G7.3 parabolas)
(Hand check - help text pages G05/05.1, G6.2/6.3, G7.2/7.3. X is a diameter, the plane G18 - Z first, X second. Below - r is X/2.)
G00 X0 Z2
M03 S800
G98 G01 Z0 F100
(Quarter ellipse, centre Z-4 r0 - A4 along Z, B2 along X - from the end of the long axis to the end of the short one, Z-4 X4, turning from +Z to +X - the G03 way seen on the rear post. Every chord end lies on [Z+4]^2/16 + r^2/4 = 1, 36 chords within 0.001 mm.)
G6.3 X4 Z-4 A4 B2
(Q90000 - the long axis turned 90 degrees from +Z the way G02 turns, so along X - centre Z-6 r2, from the end of the short axis Z-4 r2 to the end of the long one Z-6 r6 - on [Z+6]^2/4 + [r-2]^2/16 = 1. G6.3 is modal - A, B and Q are not.)
X12 Z-6 A4 B2 Q90000
G01 Z-8
(G05 - I3 K-1 from the start Z-8 r6 - the middle point Z-9 r9 - the circle through Z-8 r6, Z-9 r9, Z-12 r10 has its centre at Z-11.5 r6.5 - radius 3.5355 to all three - and turns from +Z to +X - counter-clockwise.)
G05 X20 Z-12 I3 K-1
(G05.1 - I24 K-14 the middle point itself, X24 a diameter - r12 Z-14 - circle through Z-12 r10, Z-14 r12, Z-16 r6 - centre Z-15 r9, radius 3.1623 to all three, counter-clockwise.)
G05.1 X12 Z-16 I24 K-14
(Parabola P1000 = 1 mm, axis along Z - u = Z, v = r - from Z-16 r6 to Z-20 r10, clockwise - opening to +Z - vertex v0 = 8 - 1 x [-4]/4 = 9 and u0 = -16 - [6-9]^2/2 = -20.5 - so Z = -20.5 + [r-9]^2/2, its extreme X18 Z-20.5 - 45 chords of 0.0889 mm in r, each [4/45]^2/8 = 0.00099 mm from it at most.)
G7.2 X20 Z-20 P1000
(A = B - the arc G02 of radius 5 from Z-20 r10 to Z-25 r15 - the centre of the minor clockwise arc is Z-20 r15 - the start 90 degrees round it from the end, clockwise.)
G6.2 X30 Z-25 A5 B5
G01 X32
M30
