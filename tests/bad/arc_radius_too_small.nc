(expect NCS-E20 line 3 col 16 on gsk980tdi)
G0 X0 Z0
G2 X20 Z-10 F1 R5
M30
