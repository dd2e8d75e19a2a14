(expect PS0052 line 4 col 1 on fanuc0t)
G98 G00 X20. Z2.
G01 X40. ,C1. F100.
G00 Z-10.
M30
