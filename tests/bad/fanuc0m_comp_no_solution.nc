(expect PS0033 line 6 col 1 on fanuc0m)
(An inner arc of radius 3 after a line, with a 2.5 mm cutter on its inside: the offset line never meets the 0.5 mm offset circle.)
G21 G17 G90 G00 X0 Y0 Z5.
G41 D1 G01 X5. F100.
X10.
G03 X4. Y0 R3.
G01 X0
G40 X-10.
M30
