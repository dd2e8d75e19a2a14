(expect NCS-E57 line 4 col 1 on gsk980tdi)
G97 M03 S500
G00 X0 Z3
G84 Z-15 F1.5
M30
