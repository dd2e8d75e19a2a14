(The YASNAC LX3 manual's G92 example N50-N54. The manual says T, S and M for G92 come in earlier blocks: the first)
(block here is ncsight's addition. MOO in the OCR text is M00, MAA an unreadable M code: M30 here.)
G97 S300 M03
N50 G00 X80. Z80.8 M00 ;
N51 G92 X70. W-50.8 I-1.5 F2. ;
N52 X68.8 ;
N53 X67.8 ;
N54 G00 X100. Z100. M30 ;
