(expect NCS-E38 line 4 col 1 on fanuc0m)
(G63 tapping mode in cutter compensation is not simulated - the compensation holds moves of one block into the next.)
G41 G01 X0 Y0 D1 F100.
G63 G01 Z-10.
M30
