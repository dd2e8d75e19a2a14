(expect PS0041 line 6 col 1 on fanuc0m)
(A notch 2 mm wide with a 5 mm cutter: the compensated move of X18. would run backwards.)
G21 G17 G90 G00 X0 Y0 Z5.
G41 D1 G01 X20. F100.
Y20.
X18.
Y5.
X0
G40 X-10.
M30
