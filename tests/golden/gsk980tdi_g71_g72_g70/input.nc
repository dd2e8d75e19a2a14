(G71 type I roughing, G70 finishing, G72 facing - GSK980TDi help text G70, G71, G72 steps 1-8.)
(G71 from A X50 Z2 - depth U2 = 2 mm radius, back-off R1, allowances U1 = 0.5 radius, W0.1.)
(Contour N10-N20 - X20 at Z2, Z-10, X40, Z-20, X50. A' = X51 Z2.1, B' = X21 Z2.1, radius 25.5 and 10.5.)
(Levels every 2 mm radius from 25.5 toward 10.5 - X47, 43, 39, 35, 31, 27, 23 on the diameter;)
(X47 and X43 meet the moved contour at its last step, Z -20 + 0.1 = -19.9; X39 to X23 at Z-9.9.)
(After each cut - back-off 1 mm at 45 degrees, Z rapid back to Z2.1. Then X21, the moved contour, and back to A.)
(The contour's F0.1 and S are not used in roughing - F0.3 of the G71 block is. G70 runs the contour at F0.1.)
G97 S500 M03
G99 G0 X50 Z2
G71 U2 R1
G71 P10 Q20 U1 W0.1 F0.3
N10 G0 X20
G1 Z-10 F0.1
X40
Z-20
N20 X50
G70 P10 Q20
(G72 from X50 Z2 - depth W3, back-off R0.5, no allowance - contour N30-N40 - Z-6 at X50, X20, Z2.)
(Levels Z-1 and Z-4 - each cut along X from X50 to where the level meets the contour, X20;)
(back-off to Z+0.5 and X+1 on the diameter, X rapid back to X50; then Z-6, the contour, and back to A.)
G72 W3 R0.5
G72 P30 Q40 F0.2
N30 G0 Z-6
G1 X20
N40 Z2
(G73 from X50 Z2 - relief U3 = 3 mm radius, W1, R3 passes, allowances U1 = 0.5 radius, W0.2 - contour N50-N60,)
(a cone with an undercut, X20 Z2 to X36 Z-10, X30 Z-15, X50 Z-20 - a pocket is fine for G73.)
(Pass k moved by the allowance + relief x [3 - k] / 2 - radius 3.5 and Z 1.2, then 2 and 0.7, then 0.5 and 0.2;)
(each pass - rapid to A moved, the ns rapid moved, the rest at F0.2 - and from its end a rapid to the next.)
G0 X50 Z2
G73 U3 W1 R3
G73 P50 Q60 U1 W0.2 F0.2
N50 G0 X20
G1 X36 Z-10
X30 Z-15
N60 X50 Z-20
G0 X60 Z10
M30
