(expect NCS-E11 line 3 col 1 on gsk980tdi)
G0 X50 Z2
G94 X20 Z-1
M30
