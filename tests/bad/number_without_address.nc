(expect PS0009 line 2 col 5 on fanuc0m)
N10 21 G40
M30
