%
O0100 (GSK980TDi: positioning, U/W, arcs, dwell, feed per revolution, G96 with a G50 clamp)
(Hand check, No.022 = No.027 = 8000 mm/min, X as a diameter, lengths in mm without a point -)
(N1 - rapid to X40 Z2 - X moves 20 mm radius, Z 2 mm; each axis at 8000 mm/min - 20/8000*60 = 0.15 s)
(N3 - 300 rpm, G99 F0.2 = 60 mm/min; N4 feeds W-22 = 22 mm in 22 s -> t = 22.15)
(N5 - G02 U20 W-10 R10 from X40 Z-20 to X60 Z-30 - clockwise seen from +Y [rear tool post] puts the centre at X60 Z-20; a quarter circle)
(    length 15.708 mm at 60 mm/min = 15.708 s -> t = 37.858)
(N6 - G03 X80 Z-40 I0 K-10 - centre = start + [I, K] = X60 Z-40; a quarter circle of 15.708 mm -> t = 53.566)
(N7 - G04 P500 is 0.5 s; N8 - X1.5 dwell is 1.5 s)
(N10/N11 - G96 S120 at X80 is 120000/[pi x 80] = 477.5 rpm; facing to X20 the speed rises as 38197/D)
(  up to the G50 clamp 1500 rpm at D 25.46. Time = integral of dr / [0.2 x rpm] = [40^2 - 12.73^2]/2/3819.7 min)
(  + 2.73 mm / 300 mm/min = 11.29 s + 0.55 s = 11.85 s [x 30.017/30 for the W-1 slope])
(Times - the hand figures above are at constant speed - each move adds its time constant, 100 ms for a rapid, 50 ms for a feed or a thread run - docs/guide.md.)
N1 G0 X40 Z2 T0101
N2 M03 S300
N3 G99 F0.2
N4 G1 W-22
N5 G2 U20 W-10 R10
N6 G3 X80 Z-40 I0 K-10
N7 G04 P500
N8 G04 X1.5
N9 G50 S1500
N10 G96 S120
N11 G1 X20 W-1
N12 G97 S500 M05
N13 G0 X100 Z100
N14 M30
%
