(expect NCS-E35 line 4 col 10 on gsk980tdi)
(G85 bores in one feed - inferred - Q, R and J of G83 are not its words.)
G00 X0 Z5 M03 S500
G85 Z-10 Q2 F0.1
M30
