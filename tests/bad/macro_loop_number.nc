(expect PS0126 line 2 col 1 on fanuc0m)
WHILE [1 EQ 1] DO4
END4
M30
