(expect NCS-E46 line 3 col 1 on fanuc0m)
G0 X0. Y0. Z50.
G81 X10. Y10. Z5. R2. F100.
M30
