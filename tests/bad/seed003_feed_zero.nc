(expect PS0011 line 3 col 1 on fanuc0m)
G0 X0. Y0. Z50.
G81 X10. Y10. Z-5. R2.
M30
