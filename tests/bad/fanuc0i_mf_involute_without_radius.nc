(expect PS0241 line 5 col 1 on fanuc0i-mf)
(G03.2 needs R - the base circle's radius - as well as I/J - FANUC 16/18-MC and 30i-MA manuals)
G21 G90 G17 G00 X10. Y0. Z5.
G01 F300.
G03.2 X11.173 Y0.4063 I-10. J0.
M30
