(expect NCS-E38 line 2 col 1 on gsk980tdi)
M98 P1234
M30
