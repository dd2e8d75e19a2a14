(expect NCS-E38 line 4 col 12 on gsk980tdi)
(G07.1 type II - the cylindrical interpolation roughing cycle with J L R K - help text G7.1 - is not simulated yet.)
G00 X44 Z5 C0
G07.1 C20. J2. L3 R0.5 K0.2
M30
