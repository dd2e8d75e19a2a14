(expect NCS-E55 line 9 col 1 on gsk980tdi)
(GSK980TDi help text, G71 note 4: no M98/M99 between ns and nf - the roughing refuses it, no G70 needed)
G99 M03 S500
G00 X40. Z2.
G71 U1. R0.5
G71 P10 Q30 U0.5 W0.1 F0.2
N10 G00 X20.
G01 Z-10.
M98 P1000
N30 X40.
M30
O1000
M99
