(expect NCS-E35 line 4 col 5 on gsk980tdi)
G97 S200 M03
G0 X0 Z5
G33 X10 Z-20 F1.5
M30
