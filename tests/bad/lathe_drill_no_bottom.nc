(expect NCS-E36 line 3 col 1 on gsk980tdi)
G0 X10 Z2
G83 X0 Q1000 F0.1
M30
