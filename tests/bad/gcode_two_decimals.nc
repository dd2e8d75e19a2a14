(expect NCS-E10 line 3 col 1 on gsk988t)
M14
G32.16 W-20 F2 S500
M30
