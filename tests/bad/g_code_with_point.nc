(expect NCS-E10 line 2 col 1 on gsk980tdi)
G00.0 X10
M30
