O0800 (FANUC 0-M - G41 D1 around an outline with inner, outer, sharp and arc corners - setup.toml, radius 2.5)
G21 G17 G90 G40 G54
G00 X0 Y-10. Z5.
G01 Z-3. F300.
G41 D1 Y0
Y30.
X10.
X15. Y45.
X20. Y30.
Y15.
X30.
G02 X40. Y5. R10.
G01 Y0
X0
G40 X-10.
G00 Z5.
M30
