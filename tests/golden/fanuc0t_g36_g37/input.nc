(G36/G37 automatic tool compensation - no sensor in a simulation - the tool reaches the measuring position, the offset stays, warning NCS-W35 - docs/commands/g27_g31_g60.md.)
(Line 4 - G36 X40. from X60 - at rapid to the approach distance before it - measure_approach_mm 5 on the radius - X50 - then the measuring feed 100 mm/min to X40 - 5 mm in 3 s plus 0.05 s.)
(Line 6 - G37 Z0 from Z5 - no farther than the approach distance - all at the measuring feed.)
G98 G00 X60. Z5.
G36 X40.
G00 X60.
G37 Z0
M30
