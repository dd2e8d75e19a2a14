(expect NCS-E33 line 2 col 4 on gsk980tdi)
G0 X99999999. Z1.
M30
