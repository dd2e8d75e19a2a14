(expect NCS-E85 line 5 col 1 on gsk980tdi)
(G22 X Z the upper limits, I K the lower, machine coordinates: the tool may not enter the box)
G0 X80 Z10
G22 X40 Z0 I0 K-50
G0 X20 Z-10
M30
