(expect PS0112 line 3 col 1 on fanuc0m)
#1 = 0
#2 = 10 / #1
M30
