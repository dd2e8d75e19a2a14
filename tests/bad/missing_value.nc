(expect NCS-E05 line 2 col 4 on gsk988t)
G1 X Z10 F100
M30
