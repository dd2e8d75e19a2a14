(expect PS0111 line 2 col 1 on fanuc0m)
#1 = EXP[1000]
M30
