(expect NCS-E33 line 3 col 5 on fanuc0m)
(G30 returns to the 2nd, 3rd or 4th reference point: P2-P4.)
G30 P5 Z0.
M30
