(expect NCS-E36 line 2 col 1 on fanuc0m)
G10 L2 Z-300.
M30
