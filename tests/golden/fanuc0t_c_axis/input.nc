(FANUC 0-T with the C axis the setup declares - C absolute - H incremental - degrees.)
(Line 7 - G00 C90. - 90 deg at 10800 deg/min - 0.6 s. Line 8 - G98 G01 H-45. F1000. - to C45 at 1000 deg/min - 2.7 s + 0.05 s.)
(Line 9 - G01 Z-10. C0 - Z from 2 to -10, 12 mm, with 45 deg - length 46.57 - Z at 1000 x 12 / 46.57 = 257.66 mm/min - C at 1000 x 45 / 46.57 = 966.24 deg/min - the same 2.795 s plus 0.05 s.)
(Lines 10-11 - G00 Y5. then V-2. to Y3 - the Y axis the setup adds, V its incremental address.)
(Line 12 - C and H together - an alarm.)
G98 G00 X20. Z2.
G00 C90.
G01 H-45. F1000.
Z-10. C0
G00 Y5.
V-2.
G00 C10. H10.
M30
