(expect NCS-E85 line 4 col 1 on gsk980tdi)
(G22 X Z the upper limits, I K the lower, machine coordinates, X a diameter: help text G22/23; the tool at X20 Z-10 stands in it)
G0 X20 Z-10
G22 X40 Z0 I0 K-50
M30
