(expect PS0124 line 4 col 1 on fanuc0m)
(a WHILE whose END is missing: alarm 124 at the WHILE before the body runs, not a run to M30)
#1 = 0
WHILE [1 EQ 1] DO 1
G0 X1. Y1.
#1 = #1 + 1
M30
