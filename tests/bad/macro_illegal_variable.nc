(expect PS0115 line 2 col 1 on fanuc0m)
#250 = 5
M30
