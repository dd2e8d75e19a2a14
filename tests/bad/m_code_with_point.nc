(expect PS0007 line 2 col 1 on fanuc0m)
M3.5
M30
