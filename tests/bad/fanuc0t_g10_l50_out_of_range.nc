(expect NCS-E33 line 4 col 7 on fanuc0t)
(5130 - the G92 chamfer in 0.1 lead - is 0 to 127 here - G10 L50 writes it as --param would.)
G10 L50
N5130 R200
G11
M30
