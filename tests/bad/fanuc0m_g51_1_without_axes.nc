(expect NCS-E36 line 3 col 1 on fanuc0m)
(G51.1 names the axes it mirrors)
G51.1
M30
