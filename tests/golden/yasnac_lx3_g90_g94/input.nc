O0197 (YASNAC LX3 - G90 and G94 with the taper I)
(Hand check - the LX3 manual's G68 page - I command for canned cycle taper X-axis distance - the box of the FANUC 0-T G90/G94 with I in place of R - inferred.)
G99 G97 S800 M03
G00 X50. Z2.
(G90 X40. Z-20. I-2. - the cut start radius 20 - 2 = 18 - X36 Z2 at rapid - feed to X40 Z-20 - feed out to X50 - rapid back to Z2.)
G90 X40. Z-20. I-2. F0.2
G00 X50. Z2.
(G94 X20. Z-2. I-1. - the cut start Z-2 - 1 = Z-3 at X50 at rapid - feed to X20 Z-2 - feed back to Z2 - rapid back to X50.)
G94 X20. Z-2. I-1. F0.2
G00 X100. Z100.
M30
