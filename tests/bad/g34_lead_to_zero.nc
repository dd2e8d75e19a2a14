(expect NCS-E51 line 4 col 1 on gsk980tdi)
G97 S200 M03
G0 X40 Z5
G34 Z-40 F2 R-0.5
M30
