(expect PS0034 line 5 col 1 on fanuc0m)
(G39 with a direction right after G41 - no compensated move before it to turn from.)
G21 G17 G90 G00 X0 Y0 Z5.
G41 D1
G39 I10. J0
X30.
G40 X50.
M30
