(expect NCS-E10 line 5 col 1 on yasnac-lx3)
(G68 is given with tool nose radius compensation cancelled - YASNAC LX3 manual 2.8.24, cautions c.)
G00 X40. Z5.
G98 G42 G01 X30. F100.
G68
M30
