(expect NCS-E40 line 3 col 1 on fanuc0m)
G0 X0. Y0. Z50.
G83 X10. Y10. Z-200. R2. Q0.0001 F100. K9999
M30
