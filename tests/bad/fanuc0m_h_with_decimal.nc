(expect NCS-E33 line 2 col 10 on fanuc0m)
G43 Z50. H1.5
M30
