(expect NCS-E10 line 4 col 1 on gsk980tdi)
(G12.1 with the C axis at 30 degrees - help text G12.1 note 4 - polar interpolation starts at angle 0.)
G00 X40 Z2 C30
G12.1
M30
