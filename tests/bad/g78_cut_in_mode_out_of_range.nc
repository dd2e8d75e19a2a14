(expect NCS-E33 line 4 col 5 on gsk980tdi)
G97 S300 M03
G0 X70 Z5
G78 P000460
M30
