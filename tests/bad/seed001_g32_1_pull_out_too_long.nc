(expect NCS-E42 line 4 col 1 on gsk988t)
M14
G00 X30 Z3
G32.1 W-10 F2.0 S500 J1 K12
M30
