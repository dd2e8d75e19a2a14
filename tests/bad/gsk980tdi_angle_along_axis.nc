(expect NCS-E93 line 3 col 10 on gsk980tdi)
G98 G00 X20. Z2.
G01 X40. Q180500 F100
M30
