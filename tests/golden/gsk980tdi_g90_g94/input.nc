(G90 and G94 single cycles - GSK980TDi help text G90 and G94, steps 1-4.)
(G90 from X50 Z2 - X rapid to the cut start, feed to the end point, feed X back to X50, Z rapid back to Z2.)
(Repeat blocks give only X - Z-30 and F stay from the G90 block.)
(X38 R-2 - taper, the cut start is at X 38 + 2 x -2 = 34 on the diameter, the end at X38 Z-30.)
(G94 from X50 Z2 - Z rapid to Z-1, feed X to X20, feed Z back to Z2, X rapid back to X50; the repeat gives only Z.)
(G99 F0.2 at 500 rpm is 100 mm/min, F0.1 is 50 mm/min.)
G97 S500 M03
G99 G0 X50 Z2
G90 X46 Z-30 F0.2
X42
X38 R-2
G94 X20 Z-1 F0.1
Z-2
G0 X60
M30
