(expect NCS-E80 line 6 col 1 on gsk980tdi)
(GSK980TDi help text, G40-G42 note 2: start-up and cancel only in G00 or G01.)
T0101
G00 X20. Z2.
G42 G01 Z0 F100
G40 G02 X30. Z-5. R5.
M30
