(expect NCS-E56 line 3 col 1 on gsk980tdi)
(G16 on the GSK980TDi is for the polar interpolation plane - help text G12.1/13.1 - not the ZX plane.)
G16
M30
