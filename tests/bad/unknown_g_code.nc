(expect NCS-E10 line 2 col 1 on yasnac-lx3)
G12.1
M30
