(expect PS0078 line 7 col 1 on fanuc0t)
(M99 P returns to N30 of the caller - it has none.)
O0001
M98 P0100
N20 M30
O0100
M99 P30
