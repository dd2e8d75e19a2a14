(FANUC 0-T G83 with Q under 5101 bit 2 = 1: the peck drilling cycle - back to the R level after each peck, down again to 5115 = 0.5 mm short of the last depth.)
(From X0 Z5. - R-3.: the R level Z2 - Q4000: feed to Z-2., rapid to Z2, rapid to Z-1.5, feed to Z-6., rapid Z2, rapid Z-5.5, feed to Z-10., rapid Z2, rapid Z-9.5, feed to Z-12.)
(dwell 0.5 s, rapid to Z5. - K2 drills the same hole twice.)
G99 G97 S1000 M03
G00 X0. Z5.
G83 Z-12. R-3. Q4000 P500 F0.1 K2
G80
M30
