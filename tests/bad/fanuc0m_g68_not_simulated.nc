(expect NCS-E38 line 2 col 1 on fanuc0m)
G68 X0. Y0. R45.
M30
