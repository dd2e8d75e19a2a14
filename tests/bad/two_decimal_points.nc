(expect PS0007 line 2 col 4 on fanuc0m)
G0 X-4.5. Z0.
M30
