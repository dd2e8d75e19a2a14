(expect PS0045 line 3 col 1 on fanuc0m)
G0 X0. Y0. Z50.
G83 X10. Y10. Z-20. R2. F100.
M30
