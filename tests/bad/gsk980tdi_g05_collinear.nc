(expect NCS-E86 line 5 col 1 on gsk980tdi)
(G05 - the middle point Z-5 r5 lies on the line from Z0 r0 to Z-10 r10 - help text G05 note 2.)
G00 X0 Z0
G98 G01 F100
G05 X20 Z-10 I5 K-5
M30
