(expect PS0011 line 3 col 1 on fanuc0m)
G0 X0. Y0. Z0.
G1 X10.
M30
