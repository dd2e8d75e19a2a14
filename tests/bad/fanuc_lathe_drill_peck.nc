(expect NCS-E38 line 4 col 16 on fanuc0t)
G99 M03 S1000
G00 X0 Z5.
G83 Z-20. R-3. Q2000 F0.1
M30
