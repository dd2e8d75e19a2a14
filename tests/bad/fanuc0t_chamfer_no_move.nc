(expect PS0051 line 4 col 1 on fanuc0t)
G98 G00 X20. Z2.
G01 X40. ,R1. F100.
M30
