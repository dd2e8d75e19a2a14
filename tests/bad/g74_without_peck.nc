(expect NCS-E36 line 4 col 1 on gsk980tdi)
G97 S600 M03
G99 G0 X20 Z1
G74 X20 Z-5 F0.1
M30
