(expect NCS-E33 line 2 col 7 on gsk980tdi)
G1 X1 F-100
M30
