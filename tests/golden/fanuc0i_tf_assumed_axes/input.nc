(fanuc0i-tf without a setup - the turning centre's C - H incremental - and Y - V incremental - are taken - each with warning NCS-W39 at its first word - docs/setup.md.)
(Line 6 - C to 90 at 10800 deg/min - 0.5 s plus 0.1 s. Line 7 - G28 H0 - C to its reference 0 - 0.6 s.)
(Line 8 - Y to 10 at rapid - 8000 mm/min - line 9 - V-5 to Y5 with C to 45 - the turn longer by 0.23 s.)
(Line 5 - G28 U0 W0 - X and Z to the profile's reference point X200 Z200 - the C and Y are not named.)
G98 G28 U0. W0.
G00 C90.
G28 H0.
G00 Y10.
G00 V-5. C45.
M30
