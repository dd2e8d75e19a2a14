(Hand check - N51 G92 X70. W-50.8 I-1.5 F2. from A = X80 Z80.8 - the cut end C is X70 Z30,)
(the cut start B is C's X plus I - radius 35 - 1.5 = 33.5 - X67 - at A's Z. Rapid to X67 Z80.8,)
(thread to X70 Z30 - lead 2 - rapid X80, rapid Z80.8. N52 and N53 give only X - the cycle)
(repeats with the same Z, I and F - seed 004 - modal X-only continuation. 50.8 mm at)
(2 x 300 = 600 mm/min is 5.08 s per pass.)
(Seed 004 example N50-N54. The manual says T, S and M for G92 come in earlier blocks: the first)
(block here is ncsight's addition. MOO in the OCR text is M00, MAA an unreadable M code: M30 here.)
(Times - the hand figures above are at constant speed - each move adds its time constant, 100 ms for a rapid, 50 ms for a feed or a thread run - docs/guide.md.)
G97 S300 M03
N50 G00 X80. Z80.8 M00 ;
N51 G92 X70. W-50.8 I-1.5 F2. ;
N52 X68.8 ;
N53 X67.8 ;
N54 G00 X100. Z100. M30 ;
