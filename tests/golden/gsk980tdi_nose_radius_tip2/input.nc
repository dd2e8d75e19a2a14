O0701 (GSK980TDi - G41 nose radius compensation in a bore, tip 2, R0.4 - setup.toml)
T0202
G99 G97 S800 M03
G00 X40. Z2.
G41 G01 Z0 F0.1
X36. Z-2.
Z-20.
G02 X30. Z-23. R3.
G01 X24.
G40 G00 Z5.
M30
