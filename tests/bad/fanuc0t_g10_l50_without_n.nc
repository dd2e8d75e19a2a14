(expect NCS-E36 line 4 col 1 on fanuc0t)
(A parameter line needs N, the parameter's number.)
G10 L50
R20
G11
M30
