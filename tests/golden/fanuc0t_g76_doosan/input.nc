(The Doosan O0201 thread, corpus - inch, least increments 0.0001 in - on fanuc0t.)
(G76P040000Q30R30 - m 4, r 00, a 00, dmin Q30 = 0.003 in, allowance R30 = 0.003 in.)
(G76X1.911Z-.5P645Q180F.1 - root X1.911, Z-0.5, height 0.0645 in, first depth 0.018 in, lead 0.1 in.)
(Depths in inch - 0.018, 0.02546, 0.03118, 0.036, 0.04025, 0.04409, 0.04762, 0.05091, 0.054, 0.05692, 0.0597, 0.0615 = k - d, then 4 x 0.0645.)
G20 G99
G97 S600 M03
G0 X2.1 Z.25
G76P040000Q30R30
G76X1.911Z-.5P645Q180F.1
G0 X3. Z3.
M30
