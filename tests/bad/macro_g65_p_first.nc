(expect NCS-E66 line 2 col 5 on gsk980tdi)
G65 A1. B2. P9100
M30
O9100
M99
