O0330 (FANUC 0-M - G33 thread cutting on a machining centre - a single-point bar in a bore)
(Hand check - FANUC 0i-MC manual, G33 IP_ F_ - the long axis moves F per spindle revolution, synchronised from the one-revolution signal; the 0-M's G33 is the lathes' G32.)
G21 G17 G90 G54 G00 X0 Y0 Z5. S300 M03
(Z5. to Z-20. - 25 mm at 1.5 x 300 = 450 mm/min - 3.333 s and the acceleration - from 0 degrees.)
G33 Z-20. F1.5
(Oriented stop, off the thread, out, back, the spindle on again - then the second start - Q180000 - 180 degrees - warning NCS-W16: another groove, as meant.)
M19
G00 X1.
Z5.
X0 M03
G33 Z-20. F1.5 Q180000
G00 Z50.
M30
