(expect NCS-E37 line 2 col 5 on gsk980tdi)
G04 G01 X1
M30
