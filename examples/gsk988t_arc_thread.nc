(The GSK988T manual's G32.2/G32.3 example. The manual shows it without a feed for the G1 block, as an excerpt of)
(a longer programme: F100 on the first line is ncsight's addition so that G1 can move.)
G98 F100
G1 X10 Z-15
M15
M03 S200
G32.3 W-10 F2 R10
M30
