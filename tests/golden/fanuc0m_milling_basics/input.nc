O0200 (FANUC 0-M: G90/G91, arcs in three planes, least-increment lengths, inch)
(Hand check - X100 without a point is 100 x 0.001 = 0.1 mm, and check warns about it.)
(Rapid X 15000, Z 12000 mm/min [518, 520] - G0 Z50. takes 50/12000*60 = 0.25 s.)
(Times - the hand figures above are at constant speed - each move adds its time constant, 100 ms for a rapid, 50 ms for a feed or a thread run - docs/guide.md.)
G21 G17 G90
G0 X100 Y0. Z50.
G1 Z-1. F600
G91 X10. Y10.
G2 X10. Y0. R5.
G90 G18 G3 X0.1 Z-1. I-10. K0
G19 G2 Y0. Z-1. J-5. K0.
G20 G0 X1. Y1.
G21 M5
M30
