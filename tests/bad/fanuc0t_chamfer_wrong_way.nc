(expect PS0051 line 5 col 1 on fanuc0t)
(K2. asks for the next move toward +Z - Z-20. goes toward -Z.)
G98 G00 X20. Z2.
G01 X40. K2. F100.
Z-20.
M30
