(expect PS0010 line 3 col 1 on fanuc0m)
(G51 scaling is an option: without the setting scaling_option, IMPROPER G-CODE)
G51 X0 Y0 P2000
M30
