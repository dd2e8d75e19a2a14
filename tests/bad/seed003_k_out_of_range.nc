(expect NCS-E33 line 3 col 31 on fanuc0m)
G0 X0. Y0. Z50.
G81 X10. Y10. Z-20. R2. F100. K10000
M30
