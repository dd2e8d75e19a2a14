(expect NCS-E38 line 5 col 5 on fanuc0m)
(G39 I_ J_ - the direction of a corner not followed by a move - is not simulated yet.)
G00 X-20. Y0
G41 G01 X0 Y0 D1 F100.
G39 I1. J0
Y20.
M30
