(expect NCS-E22 line 4 col 1 on gsk980tdi)
(G05 with neither I nor K - help text G05 note 3.)
G00 X0 Z0
G98 G05 X20 Z-10 F100
M30
