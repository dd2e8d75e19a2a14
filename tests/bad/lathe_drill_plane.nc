(expect NCS-E56 line 4 col 1 on gsk980tdi)
G17
G0 X10 Z2
G83 Z-5 F0.1
M30
