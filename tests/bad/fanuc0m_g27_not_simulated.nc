(expect NCS-E38 line 2 col 1 on fanuc0m)
G27 Z0.
M30
