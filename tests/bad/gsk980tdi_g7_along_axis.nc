(expect NCS-E86 line 5 col 1 on gsk980tdi)
(G7.2 - from Z0 to Z-10 at the same X - the chord is parallel to the parabola's axis, Q0 along Z - help text G7.2 note 4.)
G00 X20 Z0
G98 G01 F100
G7.2 Z-10 P2000
M30
