(expect NCS-E38 line 4 col 1 on fanuc0m)
(G83 under scaling: its Q is not scaled on the FANUC, so ncsight does not simulate it)
G51 X0 Y0 Z0 P2000
G99 G83 X10. Y0 Z-10. R2. Q3. F100.
M30
