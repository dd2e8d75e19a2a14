(expect PS0009 line 3 col 1 on fanuc0t)
(G12.1 on a machine whose setup declares no C axis.)
G12.1
M30
