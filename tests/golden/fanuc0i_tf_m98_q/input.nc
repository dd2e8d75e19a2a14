O0001 (M98 Q - the FANUC 0i-F's call of a sequence number of the same programme - docs/commands/m98_m99.md)
(Line 7 - M98 Q100 L2 - the blocks from N100 to M99 run twice - each steps Z by -1 - then line 8.)
(Line 9 - M98 Q200 - N200 calls N100 once more - two levels deep - then back to line 10.)
(Rapid 8000 mm/min reached in 0.2 s - a short move accelerates half way - 2 x the square root of half its length over 666.7 mm/s2 - each W-1 0.0548 s - X10 to X30 0.1732 s.)
G98
G00 X10. Z0
M98 Q100 L2
G00 X30.
M98 Q200
G00 X40.
M30
N100 G00 W-1.
M99
N200 M98 Q100
M99
