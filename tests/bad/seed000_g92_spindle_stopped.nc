(expect NCS-E39 line 3 col 1 on gsk980tdi)
G0 X65 Z5
G92 X58.7 Z-28 F3
M30
