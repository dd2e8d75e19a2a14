(expect PS0076 line 2 col 1 on fanuc0m)
G65 A1. B2.
M30
