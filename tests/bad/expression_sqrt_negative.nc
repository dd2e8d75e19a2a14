(expect NCS-E32 line 2 col 7 on gsk980tdi)
G1 X1 F[SQRT[-1]]
M30
