(expect PS0010 line 2 col 1 on fanuc0m)
G32 X10. Z-5. F1.5
M30
