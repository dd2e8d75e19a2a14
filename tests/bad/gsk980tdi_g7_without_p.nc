(expect NCS-E36 line 4 col 19 on gsk980tdi)
(G7.3 with P0 - help text G7.2 note 1.)
G00 X20 Z0
G98 G7.3 X30 Z-10 P0 F100
M30
