(expect NCS-E33 line 3 col 5 on fanuc0t)
(G10 P sets wear offsets P1-P64 and geometry offsets P10001-P10064.)
G10 P65 X0.2
M30
