(expect NCS-E38 line 4 col 16 on fanuc0t)
(FANUC 0-T G84 with Q is peck tapping, by parameter 5104 bit 6: not simulated)
G99 S500 M03 G00 X0. Z5.
G84 Z-10. R-2. Q3000 F1.0
M30
