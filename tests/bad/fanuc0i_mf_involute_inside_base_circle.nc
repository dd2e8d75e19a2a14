(expect PS0242 line 5 col 1 on fanuc0i-mf)
(The start point X5 Y0 is 5 mm from the centre - inside the base circle of R10)
G21 G90 G17 G00 X5. Y0. Z5.
G01 F300.
G03.2 X11.173 Y0.4063 I-5. J0. R10.
M30
