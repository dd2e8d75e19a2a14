(fanuc0i-tf without a setup - P11 and P12 select the main and the sub spindle - warning NCS-W39 at the first - docs/setup.md.)
(Line 4 - P12 alone selects the sub spindle - line 5 - S500 M04 for it - line 6 - G50 S3000 clamps - line 7 - to X40 - line 8 - G96 S200 M03 P11 the main one - 200000 over pi times 40 - 1591.5 rpm.)
G99 G97
P12
S500 M04
G50 S3000
G00 X40. Z2.
G96 S200 M03 P11
M30
