O0900 (FANUC 0-M - G45 to G48 tool position offset with D1 = 2.5 - setup.toml)
(Hand check - each axis's move of the block is longer or shorter by 2.5 once or twice, in its direction.)
G21 G17 G91 G00 X0 Y0 Z0
(G45 increase - X20 moves 22.5.)
G45 X20. D1
(G46 decrease - X20 moves 17.5 - at X40.)
G46 X20. D1
(G47 double increase - Y-10 moves -15.)
G47 Y-10. D1
(G48 double decrease - Y-10 moves -5 - at Y-20.)
G48 Y-10. D1
(An incremental zero moves by the value, signed by the zero - X0 +2.5, X-0 -2.5 - back at X40.)
G45 X0 D1
G45 X-0 D1
(Absolute - from X40 to X0 is -40, made -42.5 - at X-2.5.)
G90 G45 X0. D1
M30
