(G71 type II - the ns block names X and Z - over a contour with one pocket. GSK980TDi help text G71 type II;)
(its path is given only in figures: ncsight's path is the assumption of docs/commands/g70_g71_g72.md.)
(Radius values: A = 25, 2. Contour B 10, 2 - out to 20, -10 - into the pocket to 15, -15 - out to 25, -20.)
(Dd 2, e 0.5, no allowance: levels 23, 21, ... 11 - B at 10 is the deepest point.)
(Levels 23 and 21 meet the last rise at Z -19 and -18. Level 19 cuts from Z2 to -8.8 - 10 + 10.8 x 10/12 = 19 -,)
(backs off to 19.5, -8.3, rises to 21.5 - e over level 21, the last one cut over the ridge top 20 -,)
(rapids to the pocket edge Z-11, down to 21, feeds in to 19 and cuts to -17; back at 21.5 to Z2.)
(Level 17 the same with the pocket from -13 to -16; levels 15 to 11 only from Z2. Then B, the contour, A.)
G99 M03 S500
G00 X50 Z2
G71 U2 R0.5
G71 P10 Q20 U0 W0 F0.2
N10 G00 X20 Z2
G01 X40 Z-10
X30 Z-15
N20 X50 Z-20
G00 X60
M30
