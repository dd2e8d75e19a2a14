(expect NCS-E83 line 12 col 1 on gsk980tdi)
(GSK980TDi help text, G40-G42 note 1: seven blocks in a row without a move in compensation.)
T0101
G00 X20. Z2.
G42 G01 Z0 F100
M08
M09
M08
M09
M08
M09
M08
M30
