O0192 (GSK980TDi - angle programming - Q the line's angle from +Z in 0.001 degree)
(Hand check - help text, angle programming - format 1 - one of X and Z with Q - the line from the start at Q reaches it - Q alone - the line ends where it meets the next block's - which gives absolute X, Z and Q. X on the diameter - the geometry in radius.)
G98 G00 X20. Z2.
G01 Z0 F100
(X40. Q135000 - from radius 10 to 20 at 135 degrees - dz = 10 / tan135 = -10 - Z-10.)
X40. Q135000
(Z-30. Q180000 - along -Z.)
Z-30. Q180000
(Q90000 D2. - a line along +X - then X80. Z-50. Q153435 - through r 40 Z-50 at 153.435 degrees - tan = -0.5 - r = 40 - 0.5 x [z + 50] meets z = -30 at r 30 - X60 Z-30. The corner arc D2 - the turn from 90 to 153.435 degrees is 63.435 - its ends 2 tan 31.7175 = 1.2361 from the corner - X57.5279 Z-30 and r 30 + 1.2361 sin153.435 = 30.5528 - z -30 + 1.2361 cos153.435 = -31.1056 - X61.1056 Z-31.1056 - centre 2 to the left of +X - X57.5279 Z-32 - counter-clockwise.)
Q90000 D2.
X80. Z-50. Q153435
(With both X and Z a line is an ordinary line - Q is not used - warning.)
X80. Z-60. Q10000
(G00 X100. Q45000 - positioning along 45 degrees - from r 40 to 50 - dz = 10 - Z-50.)
G00 X100. Q45000
M30
