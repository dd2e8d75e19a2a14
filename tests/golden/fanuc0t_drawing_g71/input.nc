O0193 (FANUC 0-T - chamfers, corner arcs and angles in a G71 contour - roughed and finished along the shape they make)
(Hand check - the contour is the one of the run - the roughing levels stop on the chamfers and arcs - G70 cuts it.)
G50 X100. Z50.
T0101
G97 S800 M03
G00 X62. Z2.
G71 U2. R1.
G71 P10 Q20 U0.5 W0.1 F0.2
N10 G00 X20.
G01 Z0 F0.1
(,C1. at X30 Z0 - X28 Z0 to X30 Z-1.)
X30. ,C1.
(,R2. between -Z and the 135-degree line - a 45-degree turn - the ends 2 tan 22.5 = 0.8284 from the corner - X30 Z-19.1716 and - along 135 degrees - Z-20.5858 X31.1716 - centre X34 Z-19.1716 - clockwise.)
Z-20. ,R2.
(X40. ,A135. - from radius 15 to 20 at 135 degrees - Z-25 - ,C1. to the -Z line - X38.5858 Z-24.2929 to X40 Z-26.)
X40. ,A135. ,C1.
Z-40.
(,A90. alone then X60. Z-50. ,A180. - the vertical line z = -40 meets r = 30 - X60 Z-40.)
,A90.
X60. Z-50. ,A180.
N20 X62.
G70 P10 Q20
G00 X100. Z50.
M30
