(expect NCS-E35 line 2 col 11 on gsk980tdi)
G1 X10 Z0 K5 F100
M30
