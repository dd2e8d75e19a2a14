(Spindle selection by P - the setup's spindle_p - FANUC multi-spindle control - inferred - docs/setup.md.)
(Line 6 - P11 at 1000 rpm forward. Line 7 - P12 at 500 rpm reverse - now selected - feeds per revolution follow it.)
(Line 9 - F0.1 per revolution of P12 - 50 mm/min - 12 mm in 14.4 s plus 0.05 s.)
(Line 10 - S800 P11 - P11 selected again, its own direction kept - forward at 800 - line 11 - F0.1 is 80 mm/min - 10 mm in 7.5 s plus 0.05 s.)
(Line 12 - M05 P12 stops P12 - line 13 - P13 is no spindle of the setup - alarm.)
G99 G97 S1000 M03 P11
S500 M04 P12
G00 X20. Z2.
G01 Z-10. F0.1
S800 P11
G01 Z-20.
M05 P12
M03 P13
M30
