(expect NCS-E36 line 4 col 1 on gsk988t)
M14
G00 X30.14 Z3
G32.1 X51.57 W-75 F2.0
M30
