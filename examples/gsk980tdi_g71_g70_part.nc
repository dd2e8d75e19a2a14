O0024 (GSK980TDi: an M24x2 stud, roughed with G71, finished with G70, threaded with G76)
(Stock: a 32 mm bar, its face at Z0 - ncsight simulate ... --stock 32x60 --expect M24x2)
T0101 (turning tool)
G99 G97 S800 M03
G0 X32. Z2.
G71 U1.5 R0.5 (depth of cut 1.5 mm a side, back-off 0.5 mm)
G71 P10 Q20 U0.4 W0.1 F0.2 (allowances 0.4 mm on the diameter, 0.1 mm on the faces)
N10 G0 X20.
G1 Z0. F0.1
X24. Z-2. (the 2 mm lead-in chamfer)
Z-30.
X28.
N20 Z-40.
G70 P10 Q20 (finishing along N10-N20)
G0 X100. Z100.
T0303 (60-degree threading tool)
G97 S500 M03
G0 X30. Z5.
G76 P021060 Q50 R0.05 (1 finishing pass, pull-out 1 lead, 60 degrees; minimum cut 0.05 mm)
G76 X21.55 Z-26. P1227 Q400 F2. (thread height 1.227 mm, first cut 0.4 mm, lead 2 mm)
G0 X100. Z100.
M30
