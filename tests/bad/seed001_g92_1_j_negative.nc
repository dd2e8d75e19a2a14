(expect NCS-E33 line 4 col 26 on gsk988t)
G0 X65 Z5
M14
G92.1 X58.7 Z-28 F3 S300 J-3 K1
M30
