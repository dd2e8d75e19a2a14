(expect PS0014 line 4 col 1 on fanuc0t)
(G34 F1. K-0.5 over 10 mm - revolutions at 0.75 and 0.25 mm, then the lead would be negative - FANUC alarm 014.)
G00 X20. Z0. S300 M03
G34 Z-10. F1. K-0.5
M30
