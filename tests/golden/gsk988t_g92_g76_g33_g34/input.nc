(GSK988T - G92 of the GSK988TA/TB manual - G76 as the GSK980TDi - G34 example of the GSK988T manual 2.16.2 - G33 as the GSK980TDi)
(G92 without J K - parameters 5130 = 10 and 5131 = 0 - pull-out 10 x 0.1 x F2 = 2 mm along Z at 45 degrees - thread to Z-18 then to X38.5 + 2 x 2 = 42.5 at Z-20.)
(The next pass X37.9 - the same pull-out to X41.9 Z-20 - then X rapid to 44 and Z rapid to 5.)
(J1 K0.5 L2 Q90000 - thread to Z-19.5 then to X38.5 + 2 = 40.5 Z-20 - two starts - 90 and 270 degrees.)
G97 S500 M03
G0 X44 Z5
G92 X38.5 Z-20 F2
X37.9
G0 X44 Z5
G92 X38.5 Z-20 F2 J1 K0.5 L2 Q90000
(G76 - the TAC example as in gsk980tdi_g76_tac - the same passes - R0.1 with its point is 0.1 mm.)
G0 X70 Z5
G76 P020560 Q150 R0.1
G76 X60.64 Z-62 P3680 Q1800 F6
(G34 - the manual's example - from X60 Z4 after U-1.0 - W-78 F4 R0.2 - revolution n at lead 4 + 0.2 x [n + 0.5].)
(J5 K2 as G32 - 14 revolutions 4.1 to 6.7 make 75.6 mm to Z-71.6 - the 15th at 6.9 goes 0.4 mm to Z-72 - K2 before Z-74.)
(Then the pull-out from X59 Z-72 to X69 Z-74 at lead 6.9 - from 360 x 0.4 / 6.9 = 20.87 degrees.)
G0 X60 Z4
G0 U-1.0
G34 W-78 F4 J5 K2 R0.2
G00 U10
Z4
(G33 - Z-20 at lead 1.5 from Z5 - in, M05, reverse, out, M05.)
G0 X0 Z5
M03
G33 Z-20 F1.5
M30
