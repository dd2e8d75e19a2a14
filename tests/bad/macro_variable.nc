(expect NCS-E38 line 2 col 1 on fanuc0m)
#1=5
M30
