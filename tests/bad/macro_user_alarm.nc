(expect PS3000 line 3 col 1 on fanuc0m)
#1 = 2
IF [#1 NE 1] THEN #3000 = 12 (TOOL WORN)
M30
