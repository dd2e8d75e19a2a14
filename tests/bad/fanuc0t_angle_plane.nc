(expect PS0212 line 3 col 10 on fanuc0t)
G98 G17 G00 X20. Z2.
G01 X40. ,A30. F100.
M30
