(expect PS0057 line 4 col 12 on fanuc0t)
G98 G00 X20. Z2.
G01 ,A150. F100.
X60. Z-20. ,A150.5
M30
