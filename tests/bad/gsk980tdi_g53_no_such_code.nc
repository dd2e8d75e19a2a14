(expect NCS-E10 line 3 col 1 on gsk980tdi)
(The GSK980TDi help text lists no G53: positioning in machine coordinates is not one of its codes.)
G53 X0 Z0
M30
