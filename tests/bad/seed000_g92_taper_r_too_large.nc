(expect NCS-E45 line 4 col 16 on gsk980tdi)
M3 S300
G0 X65 Z5
G92 X58.7 Z-28 R4 F3
M30
