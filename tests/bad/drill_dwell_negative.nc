(expect NCS-E33 line 3 col 22 on fanuc0m)
G90 G00 X0. Y0. Z10. F100.
G82 X1. Y1. Z-5. R2. P-100
M30
