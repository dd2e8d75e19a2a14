(expect PS0054 line 3 col 1 on fanuc0t)
G98 G00 X20. Z2.
G01 X40. Z-5. K-2. F100.
Z-20.
M30
