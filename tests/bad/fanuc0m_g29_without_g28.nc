(expect NCS-E88 line 4 col 5 on fanuc0m)
(G29 names Z - no G28 or G30 has given Z an intermediate point - G28 X named X only.)
G91 G28 X0.
G90 G29 Z0.
M30
