(expect PS0055 line 3 col 1 on fanuc0t)
G98 G00 X20. Z2.
G01 X40. ,C12. F100.
Z-20.
M30
