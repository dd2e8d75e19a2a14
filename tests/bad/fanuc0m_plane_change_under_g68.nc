(expect NCS-E38 line 4 col 1 on fanuc0m)
(No plane change under coordinate rotation: G69 first)
G17 G68 X0 Y0 R30.
G18
M30
