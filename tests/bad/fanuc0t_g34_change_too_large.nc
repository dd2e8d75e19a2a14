(expect PS0014 line 4 col 15 on fanuc0t)
(G34's K is at most 500 mm per revolution - FANUC alarm 014.)
G00 X20. Z0. S30 M03
G34 Z-10. F1. K600.
M30
