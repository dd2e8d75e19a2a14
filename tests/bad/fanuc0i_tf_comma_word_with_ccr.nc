(expect PS0312 line 4 col 10 on fanuc0i-tf)
(3405#4 CCR = 1 - the drawing's words are C R A without the comma - a ,A is alarm PS0312 - a secondary list of the 0i-F alarm texts)
G98 G00 X40. Z2.
G01 X60. ,A45. F100.
M30
