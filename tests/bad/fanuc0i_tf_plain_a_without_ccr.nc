(expect PS0009 line 4 col 10 on fanuc0i-tf)
(3405#4 CCR = 0 - the default - the drawing's angle is ,A - a plain A is no address of this lathe)
G98 G00 X40. Z2.
G01 X60. A45. F100.
M30
