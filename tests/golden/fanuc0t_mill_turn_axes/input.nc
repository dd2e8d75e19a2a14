(Mill-turn axes from the setup - G53 and G28 with C - H - Y and the linear B - docs/setup.md.)
(Power on at the reference X400 Z300 - machine and work coordinates agree - no offsets.)
(Rapid 8000 mm/min - parameter 1420 - each rapid plus 0.1 s - feeds plus 0.05 s.)
(Line 11 - G53 B-300 - the sub-spindle slides at the Z rapid - 300 mm is 2.25 s plus 0.1 s.)
(Line 12 - X to 100 - 150 mm radius - 1.225 s - C to 90 at 10800 deg/min - 0.6 s - with the move - no more time.)
(Line 13 - G28 H0 W0 - C and Z named - Z already at its intermediate point and home - C to its reference 0 - 0.6 s.)
(Line 14 - G01 B-500 F2000 in G98 - 200 mm at 2000 mm/min - 6 s plus 0.05 s.)
(Line 15 - G28 V0 B0 - Y has no move - B to its intermediate point 0 - 500 mm at rapid - 3.75 s plus 0.1 s - then home - no move.)
(Line 16 - G53 C45 Y20 - Y 20 mm at rapid - 0.25 s - C with it - 45 deg - 0.35 s - the turn longer by 0.1 s.)
G98
G53 B-300.
G00 X100. C90.
G28 H0 W0
G01 B-500. F2000.
G28 V0 B0
G53 C45. Y20.
M30
