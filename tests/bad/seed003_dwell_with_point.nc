(expect PS0007 line 3 col 30 on fanuc0m)
G0 X0. Y0. Z50.
G82 X10. Y10. Z-5. R2. F100. P0.5
M30
