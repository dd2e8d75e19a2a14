O0321 (GSK980TDi - G32.1 rigid thread cutting - C the start angle, F the lead, negative for a left-hand thread, J/K the pull-out, S the speed)
(Hand check - help text G32.1 - the servo spindle in position mode - M14 - turns at S and the Z axis follows it at the lead, from the spindle angle C.)
G00 X30 Z5
M14
(W-20 at F2 and S500 - 1000 mm/min - 1.2 s + 0.05 - from C90 - 90 degrees.)
G32.1 W-20 F2 S500 C90
G00 X40
Z5
X29
(F-2 - a left-hand thread: the spindle turns the other way, -500 rpm; J2 K2 - the pull-out, 2 mm out on the radius over the last 2 mm of Z, as G32's - the thread to Z-13, then to X33 at Z-15; warning NCS-W16: this pass turns the other way from the first.)
G32.1 W-20 F-2 S500 C90. J2 K2
G00 X40
M15
M30
