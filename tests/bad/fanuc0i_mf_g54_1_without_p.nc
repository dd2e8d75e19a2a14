(expect NCS-E36 line 3 col 1 on fanuc0i-mf)
(G54.1 selects an additional work system by P - 1 to 48 - here none is given)
G54.1 G00 X0 Y0
M30
