(expect NCS-E41 line 3 col 1 on gsk988t)
G00 X30.14 Z3
G32.1 X51.57 W-75 F2.0 S500
M30
