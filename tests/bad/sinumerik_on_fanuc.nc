(expect NCS-E52 line 2 col 1 on fanuc0m)
%MPF  90
N10 G81 R2=2 R3=-10 R10=5
M30
