(G78 - GSK980TDi help text - the two-block form with equal depths, alternating infeed, two starts,)
(then decreasing depths with right-flank infeed.)
(Cycle 1 - G78 P000360 Q50 R0.1 D1 L2 / G78 X28 Z-20 P1000 Q300 F3 from X32 Z5.)
(k 1.0, dd 0.3, d 0.1, equal depths - 0.3, 0.6, 0.9 = k - d, then D1 pass at 1.0.)
(Pass X = 28 + 2 x [1 - depth] - 29.4, 28.8, 28.2, 28.0.)
(Alternating infeed, a 60 - the tip [k - depth] x tan 30 off the centre, -Z flank first - start Z 4.5959, 5.2309, 4.9423, 5.)
(Two starts - each pass cut at 0 then 180 degrees, so 8 four-step cycles.)
(No J K - the pull-out is No.19 = 10 tenths of the lead = 3 mm at 45 degrees, cut to the retract distance.)
G97 S500 M03
G0 X32 Z5
G78 P000360 Q50 R0.1 D1 L2
G78 X28 Z-20 P1000 Q300 F3
(Cycle 2 - G78 P010260 Q100 R0.05 D2 L1 / G78 U-2 W-15 P600 Q250 F1.5 from X32 Z5.)
(k 0.6, dd 0.25, dmin 0.1, d 0.05, decreasing - 0.25, 0.25 sqrt2 = 0.3536,)
(0.25 sqrt3 = 0.433 is less than dmin deeper so 0.4536, 0.25 sqrt4 = 0.5 likewise so 0.5536 past k - d so 0.55,)
(then two D passes at 0.6, one start - L is kept from block to block like the other first-block data. Pass X = 30 + 2 x [0.6 - depth] - 30.7, 30.4929, 30.2929, 30.1, 30, 30.)
(Right-flank infeed - start Z = 5 + [0.6 - depth] x tan 30 - 5.2021, 5.1423, 5.0846, 5.0289, 5, 5.)
G78 P010260 Q100 R0.05 D2 L1
G78 U-2 W-15 P600 Q250 F1.5
M30
