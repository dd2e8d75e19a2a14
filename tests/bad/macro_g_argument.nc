(expect PS0129 line 2 col 11 on fanuc0m)
G65 P9100 G01 X1.
M30
O9100
M99
