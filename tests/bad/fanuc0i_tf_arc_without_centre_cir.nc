(expect PS0022 line 4 col 1 on fanuc0i-tf)
(With 3403#5 CIR = 1 a G02 with neither R nor I/K is alarm PS0022 - FANUC 0i-F parameter manual - as recalled)
G98 G00 X40. Z2.
G02 X50. Z-5. F100.
M30
