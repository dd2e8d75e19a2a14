(expect NCS-E38 line 4 col 1 on fanuc0m)
(A reference return under coordinate rotation is not simulated)
G68 X0 Y0 R30.
G28 Z0
M30
