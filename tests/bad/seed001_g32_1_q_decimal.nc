(expect NCS-E07 line 4 col 22 on gsk988t)
M14
G00 X30 Z3
G32.1 W-10 F2.0 S500 Q180.
M30
