(expect NCS-E33 line 3 col 15 on gsk980tdi)
G0 X0 Z2
G83 Z-5 Q1000 J2 F0.1
M30
