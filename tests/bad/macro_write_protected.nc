(expect PS0116 line 2 col 1 on fanuc0m)
#0 = 5
M30
