(expect NCS-E38 line 3 col 1 on fanuc0t)
G0 X20. Z2.
G84 Z-10. F1.
M30
