(expect NCS-E10 line 3 col 1 on gsk980tdi)
(The GSK980TDi help text has G10 L3 and G10 L52 only: no G10 L2.)
G10 L2 P1 Z-300
M30
