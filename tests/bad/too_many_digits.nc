(expect PS0003 line 2 col 4 on fanuc0m)
G0 X1.0000000001
M30
