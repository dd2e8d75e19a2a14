(expect NCS-E35 line 4 col 16 on fanuc0t)
(FANUC 0-T G85 boring: X C Z R P F K M - no peck depth Q)
G99 S500 M03 G00 X0. Z5.
G85 Z-10. R-2. Q3000 F0.1
M30
