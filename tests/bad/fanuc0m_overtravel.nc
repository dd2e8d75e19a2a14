(expect OT0501 line 6 col 1 on fanuc0m)
(The setup's X travel is -500 to 0 in machine coordinates; G54 puts X0 at machine X-400.)
G21 G17 G90 G54
G00 X0 Y0 Z10.
X-50.
X-150.
M30
