(expect NCS-E34 line 2 col 8 on gsk980tdi)
G0 X10 U2 Z0
M30
