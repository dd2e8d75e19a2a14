(expect NCS-E36 line 5 col 1 on fanuc0m)
G0 X0. Y0. Z50.
G81 X10. Y10. Z-5. R2. F100.
G80
G85 X20. Y20.
M30
