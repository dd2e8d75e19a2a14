(expect PS0020 line 3 col 1 on fanuc0m)
G0 X0. Y0.
G3 X10. Y0. I3. J0. F100.
M30
