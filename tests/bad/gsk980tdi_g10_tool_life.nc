(expect NCS-E38 line 3 col 1 on gsk980tdi)
(G10 L3 - tool life management data - is in the GSK980TDi help text but not simulated.)
G10 L3
M30
