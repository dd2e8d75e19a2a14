(expect PS0076 line 3 col 1 on fanuc0m)
G90 G00 X0. Y0. Z10.
M98
M30
