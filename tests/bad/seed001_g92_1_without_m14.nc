(expect NCS-E41 line 3 col 1 on gsk988t)
G0 X65 Z5
G92.1 X58.7 Z-28 F3 S300 J3 K1
M30
