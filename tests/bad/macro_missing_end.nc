(expect PS0124 line 3 col 1 on fanuc0m)
#1 = 0
WHILE [#1 GT 5] DO1
#1 = #1 + 1
M30
