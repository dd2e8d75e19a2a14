(expect PS0092 line 4 col 1 on fanuc0m)
(G27 goes to Z5. and checks the reference point: without a setup it is machine zero on this profile.)
G21 G90 G00 Z10.
G27 Z5.
M30
