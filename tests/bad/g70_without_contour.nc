(expect NCS-E53 line 4 col 1 on gsk980tdi)
G97 S500 M03
G99 G0 X50 Z2
G70 P10 Q20
M30
