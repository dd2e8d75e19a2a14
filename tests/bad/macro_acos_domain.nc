(expect NCS-E70 line 2 col 1 on gsk988t)
#1 = ACOS[2]
M30
