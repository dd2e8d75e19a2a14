(expect NCS-E89 line 5 col 1 on gsk980tdi)
(L8 - type I - needs 5.657 mm of each move; the next move is 2 mm long - help text, chamfer function, case 2.)
G98 G00 X0 Z2
G01 Z0 F100
X20 L8
Z-2
M30
