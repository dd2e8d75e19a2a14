(expect PS0119 line 2 col 1 on fanuc0t)
#1 = SQRT[-4]
M30
