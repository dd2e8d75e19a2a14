(expect NCS-E86 line 5 col 1 on gsk980tdi)
(G6.2 - the end point 30 mm away along Z, the long axis A10 only 20 mm - help text G6.2 note 5.)
G00 X20 Z0
G98 G01 F100
G6.2 Z-30 A10 B5
M30
