(expect NCS-E57 line 4 col 1 on gsk980tdi)
G97 M03 S500
M29 S300
M29
M30
