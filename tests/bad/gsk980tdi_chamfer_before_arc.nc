(expect NCS-E38 line 6 col 1 on gsk980tdi)
(A chamfer between a G01 and a G02 is not simulated yet - G01 to G01 only.)
G98 G00 X0 Z2
G01 Z0 F100
X20 L2
G02 X30 Z-5 R5
M30
