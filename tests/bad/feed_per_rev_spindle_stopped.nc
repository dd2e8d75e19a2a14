(expect NCS-E39 line 3 col 1 on gsk980tdi)
G99 F0.2
G1 X10 Z-5
M30
