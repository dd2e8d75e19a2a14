(expect NCS-E10 line 5 col 1 on gsk980tdi)
(G00 in polar coordinate interpolation - FANUC 0i-T's list of the codes allowed in it, inferred for the GSK980TDi.)
G00 X40 Z2 C0
G12.1
G00 X20 C5
M30
