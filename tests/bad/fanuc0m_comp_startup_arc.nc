(expect PS0034 line 4 col 1 on fanuc0m)
(Compensation starts in a G00 or G01 move, not in an arc.)
G21 G17 G90 G00 X0 Y0 Z5.
G41 D1 G02 X10. Y0 R5. F100.
M30
