O0191 (FANUC 0-T - direct drawing dimension programming - the angle ,A and the corners ,C ,R)
(Hand check - the angle is counter-clockwise from +Z toward +X - X on the diameter - the geometry in radius. ,C is the distance from the corner to each end of the chamfer - ,R the radius of an arc tangent to both lines.)
G50 X200. Z100.
G97 S1000 M03
G98 G00 X50. Z50.
(Form 2 - ,A30. alone then X0 Z150. ,A-45. - the lines r = 25 + tan30 x [z - 50] and r = 150 - z meet at z = 153.8675 / 1.57735 = 97.5481 - r 52.4519 - X104.9038.)
G01 ,A30. F100.
X0 Z150. ,A-45.
G00 X20. Z2.
G01 Z0
(Form 1 - X40. ,A135. - from radius 10 to 20 at 135 degrees - dz = 10 / tan135 = -10 - Z-10.)
X40. ,A135.
(Form 1 with Z - Z-30. ,A180. - a line along -Z - X stays 40.)
Z-30. ,A180.
(Form 3 - ,A90. ,C2. alone then X80. Z-40. ,A0 - the vertical line z = -30 meets r = 40 at X80 Z-30 - the chamfer 2 from the corner on each line - X76 Z-30 to X80 Z-32 - then on to Z-40.)
,A90. ,C2.
(One block without a move may come between - its S comes after the line and its chamfer.)
S500
X80. Z-40. ,A0
(Form 4 with ,R - X100. Z-50. ,R3. then Z-70. - the corner at X100 Z-50 turns from 45 degrees to -Z - D = 3 - the arc's ends 3 tan 22.5 = 1.2426 from the corner - on the first line at r 50 - 1.2426 sin45 = 49.1213 - z -50 + 0.8787 - X98.2426 Z-49.1213 - on the second at X100 Z-51.2426 - centre 3 below the second line - X94 Z-51.2426 - counter-clockwise as the path turns from 135 to 180 degrees.)
X100. Z-50. ,R3.
Z-70.
(Forms 5-8 - a chamfer and a corner arc in a row - X120. ,C1. then Z-90. ,R2. then X140. - square corners - X118 Z-70 to X120 Z-71 - then Z-88 to X124 Z-90 centre X124 Z-88 clockwise.)
X120. ,C1.
Z-90. ,R2.
X140.
G00 X200. Z100.
M30
