(expect PS0242 line 5 col 1 on fanuc0i-mf)
(The end point lies on the involute that unwinds counter-clockwise - G02.2 follows the other one - and misses it by 0.73 mm)
G21 G90 G17 G00 X10. Y0. Z5.
G01 F300.
G02.2 X11.173 Y0.4063 I-10. J0. R10.
M30
