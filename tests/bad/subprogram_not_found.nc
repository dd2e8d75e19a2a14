(expect NCS-E61 line 2 col 1 on gsk980tdi)
M98 P1234
M30
