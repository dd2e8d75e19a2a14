(The machining centre's offsets as system variables - memory C - H wear #2001 - H geometry #2201 - D wear #2401 - D geometry #2601 - G55 #5241.)
(Line 5 - X to #2203 - 120.5 - Y to #2003 times -100 - 20. Line 6 - X to #2603 - 5 - Y to #2403 times 1000 - 10.)
(Line 7 - X to #5241 plus 400 - 100 - Y to #5242 plus 150 - 0. Line 8 - #12003 = 0.02 - line 9 - Y to #2403 times 1000 - 20.)
G90 G17 G00 X0 Y0 Z0
G00 X#2203 Y[#2003 * -100]
G00 X#2603 Y[#2403 * 1000]
G00 X[#5241 + 400] Y[#5242 + 150]
#12003 = 0.02
G00 Y[#2403 * 1000]
M30
