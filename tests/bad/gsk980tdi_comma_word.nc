(expect NCS-E09 line 4 col 10 on gsk980tdi)
(A FANUC 0-T chamfer word on the GSK980TDi - the hint names L, D and Q.)
G98 G00 X20. Z2.
G01 X40. ,C1. F100
Z-20.
M30
