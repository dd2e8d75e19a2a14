(expect NCS-E36 line 4 col 1 on gsk980tdi)
(G6.3 without B - B left out is 0, an alarm - help text G6.2 note 1.)
G00 X20 Z0
G98 G6.3 X30 Z-10 A10 F100
M30
