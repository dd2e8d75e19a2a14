(expect PS0077 line 16 col 1 on fanuc0m)
(Four levels of M98 nest - FANUC 0i-TB/MB operator's manual 12.3 - the fifth call alarms.)
O9000
M98 P0001
M30
O0001
M98 P0002
M99
O0002
M98 P0003
M99
O0003
M98 P0004
M99
O0004
M98 P0005
M99
O0005
M99
