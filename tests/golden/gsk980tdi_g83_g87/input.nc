(G83 and G87 lathe drilling - GSK980TDi help text G83/87.)
(G83 J0 from Z2 to Z-10: pecks Q3000 = 3 mm, back R0.5 after each - J0 steps 2-4: feed to -1, back to -0.5,)
(feed 3.5 to -4, back to -3.5, feed to -7, back to -6.5, feed to -10, dwell P500 = 0.5 s, rapid to Z2.)
(The next block gives only the bottom: the same data drills again, to Z-12.)
(G87 J1 from X20 - radius 10 - to X4: pecks Q2000 = 2 mm radius, R1 - J1 steps 2-5: feed to radius 8,)
(rapid to the start 10, rapid to 9, feed to 6, and so on to radius 2; then back to 10.)
(Two-block style of the Chinese shop notes: G83 R0.3 stores the retract, the next G83 drills from Z1 to Z-2.)
G99 M03 S1000
G00 X0 Z2
G83 Z-10 Q3000 R0.5 P500 F0.1
Z-12
G80
G00 X20 Z-5
G87 X4 Q2000 R1 J1 F0.1
G00 X30 Z1
X0
G83 R0.3
G83 Z-2 Q1000 F0.1
G00 X30
M30
