(expect PS0128 line 3 col 1 on fanuc0m)
#1 = 5
IF [#1 GT 2] GOTO 77
M30
