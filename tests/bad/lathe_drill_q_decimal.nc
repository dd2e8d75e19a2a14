(expect NCS-E07 line 3 col 9 on gsk980tdi)
G0 X0 Z2
G83 Z-5 Q1.5 F0.1
M30
