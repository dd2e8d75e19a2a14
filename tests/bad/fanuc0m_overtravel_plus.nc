(expect OT0500 line 5 col 1 on fanuc0m)
(The setup's Y travel ends at machine Y0; G54 puts Y0 at machine Y-300.)
G21 G17 G90 G54
G00 X0 Y0 Z10.
Y301.
M30
