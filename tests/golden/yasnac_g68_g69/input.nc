O0068 (YASNAC LX3 - G68/G69 program mirror image - X mirrored about the spindle's centre line)
(Hand check - YASNAC LX3 manual 2.8.24 - under G68 the X and U commands and the arc centre's I are inverted and G02 and G03 exchanged; the block of G68 itself does not move; G69 ends it. The tool stands at X40 when G68 comes: its programmed X is then -40.)
G00 X40. Z5. S500 M03
G68
(X20. - to X-20 on the machine - across the centre line, 60 mm of X on the diameter: 30 mm radial and 5 mm of Z - at 0.2 x 500 = 100 mm/min - 18.248 s + 0.05.)
G01 X20. Z0 F0.2
(G02 R5. to X30. Z-5. - inverted: a G03 from X-20 Z0 to X-30 Z-5 about X-30 Z0 - a quarter of radius 5 - 7.854 mm - 4.712 s + 0.05.)
G02 X30. Z-5. R5.
(U10. - inverted - to X-40.)
G01 U10.
G69
G00 X40. Z5.
M30
