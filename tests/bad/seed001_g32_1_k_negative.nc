(expect NCS-E33 line 4 col 25 on gsk988t)
M14
G00 X30 Z3
G32.1 W-10 F2.0 S500 J1 K-1
M30
