(expect NCS-E09 line 2 col 4 on gsk980tdi)
G0 Y10.
M30
