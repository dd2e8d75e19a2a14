(expect NCS-E38 line 2 col 4 on fanuc0t)
G0 G53 X0. Z0.
M30
