(YASNAC LX3 G32 - no LX3 page at hand - inferred - the FANUC 0-T's G32 with E for the lead as the LX3's G92 takes it.)
(Line 5 - X30 Z5 - line 6 - thread to Z-20 at lead 1.5 - 25 mm at 500 rpm is 750 mm/min - 2 s plus the 0.05 s acceleration - no pull-out.)
(Lines 7-9 - out to X40 - back to Z5 - in to X29. Line 10 - G32 W-25. E1.5 - the same thread, the lead given by E.)
G97 S500 M03
G00 X30. Z5.
G32 Z-20. F1.5
G00 X40.
Z5.
X29.
G32 W-25. E1.5
G00 X40.
M30
