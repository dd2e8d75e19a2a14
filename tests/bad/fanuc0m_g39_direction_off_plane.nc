(expect NCS-E35 line 6 col 5 on fanuc0m)
(G39's direction is given in the plane's I and J in G17 - K is off the plane.)
G00 X-20. Y0
G41 G01 X0 Y0 D1 F100.
Y20.
G39 K1.
X30.
M30
