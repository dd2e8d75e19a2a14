(expect NCS-E38 line 2 col 1 on fanuc0m)
G29 Z0.
M30
