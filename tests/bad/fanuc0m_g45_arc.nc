(expect NCS-E38 line 3 col 1 on fanuc0m)
(G45 with a circular move is not simulated yet; G00 or G01 only.)
G45 G02 X10. Y10. R10. D1 F100.
M30
