(P11 in a block of its own selects the spindle the next S and M codes are for - docs/setup.md.)
(Line 5 - P12 alone - line 6 - S500 M04 for the sub spindle - line 7 - P11 - line 8 - S1000 M03 for the main one.)
(Line 9 - P12 selected again - its S500 reverse kept - feeds per revolution follow it - line 11 F0.1 is 50 mm/min - 10 mm in 12 s plus 0.05 s.)
G99 G97
P12
S500 M04
P11
S1000 M03
P12
G00 X20. Z2.
G01 Z-8. F0.1
M30
