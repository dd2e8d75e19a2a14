(G70 with a range other than the G71's - FANUC - G70 runs the programme's blocks N ns to N nf - docs/commands/g70_g71_g72.md.)
(Line 9 - G71 P10 Q20 roughs N10 to N20 - then N30 - line 13 - runs as an ordinary block at the F in force - the G71's F0.25.)
(Line 15 - G70 P10 Q30 - N10 - line 10 - to N30 - line 13 - run for real at their F - then back to the start point X52 Z2.)
(G99 F0.1 at S800 is 80 mm/min - N10 rapids to X30 at Z2 - 22 mm along Z is 16.5 s plus 0.05 s - 10 mm in X as a radius 7.5 s plus 0.05 s - N30 10 mm 7.55 s.)
(The records of the blocks G70 runs - and its return - are one call level deep - call_depth 1.)
(Then line 16.)
G99 G00 X52. Z2. S800 M03
G71 U1. R0.5
G71 P10 Q20 U0.4 W0.1 F0.25
N10 G00 X30.
G01 Z-20. F0.1
N20 X50.
N30 G01 Z-30.
G00 X52. Z2.
G70 P10 Q30
G00 X100. Z100.
M30
