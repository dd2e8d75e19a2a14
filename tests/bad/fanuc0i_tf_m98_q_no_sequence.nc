(expect PS0078 line 4 col 1 on fanuc0i-tf)
(M98 Q200 calls N200 of the same programme - it has none)
O0001
M98 Q200
M30
N100 G00 W-1.
M99
