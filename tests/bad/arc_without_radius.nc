(expect PS0022 line 3 col 1 on fanuc0m)
G0 X0. Y0.
G2 X10. Y0. F100.
M30
