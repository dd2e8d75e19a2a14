(expect PS0053 line 3 col 15 on fanuc0t)
G98 G00 X20. Z2.
G01 X40. K-2. R1. F100.
Z-20.
M30
