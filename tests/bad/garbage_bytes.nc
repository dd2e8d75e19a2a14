(expect NCS-E30 line 2 col 7 on gsk980tdi)
G0 X1 ÿþ Z1
M30
