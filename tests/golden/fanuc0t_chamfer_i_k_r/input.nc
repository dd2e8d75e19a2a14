O0196 (FANUC 0-T - chamfering and corner R at a right angle - I, K, R in G01)
(Hand check - FANUC 0i-T and 30i manuals - G01 X_ K_ - a 45-degree chamfer of legs K to a next move along Z - G01 Z_ I_ - legs I to a move along X - G01 Z_ R_ or X_ R_ - a corner arc of radius R - the sign the next move's way. I and K are radius values - inferred.)
G98 G00 X20. Z2.
G01 Z0 F100.
(X40. K-2. - the face up to radius 20 stops 2 short - X36 Z0 - the chamfer to X40 Z-2 - the next move goes -Z as K says.)
X40. K-2.
(Z-20. R3. - the arc from Z-17 X40 to X46 Z-20 about X46 Z-17 - clockwise - the next move goes +X.)
Z-20. R3.
(X60. K-1. - X58 Z-20 to X60 Z-21.)
X60. K-1.
(Z-30. I5. - the line along -Z stops 5 short at Z-25 - the chamfer to radius 35 - X70 Z-30 - the next move goes +X.)
Z-30. I5.
X80.
G00 X100.
M30
