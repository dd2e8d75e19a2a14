(G02.2/G03.2 involute interpolation - FANUC 16/18-MC and 30i-MA manuals - an option of the 0i-MF - docs/commands/g02_2_g03_2.md.)
(Base circle R10 about X0 Y0. Its involute from X10 Y0 - at roll t - is X = 10[cos t + t sin t] - Y = 10[sin t - t cos t].)
(Line 9 - G03.2 from X10 Y0 - roll 0 - I-10 J0 the centre from the start - to roll 0.5 - X11.173 Y0.4063 - unwinding counter-clockwise.)
(Chords of 0.001 mm sag - a chord over roll dt sags 10 t dt^2/8 - equal steps in w = t^1.5 of 1.5 sqrt[8 x 0.001/10] = 0.042426 - 0.5^1.5 = 0.353553 - 9 chords.)
(Chord 1 ends at w = 0.039284 - t = 0.039284^[2/3] = 0.115573 - X = 10[0.993329 + 0.115573 x 0.115316] = 10.0666 - Y = 10[0.115316 - 0.115573 x 0.993329] = 0.0051. The chords after the first carry a time constant of 0 - one interpolation. The last ends at the end point exactly.)
(Line 10 - G02.2 back to X10 Y0 - the same involute wound up clockwise - the same 9 points in reverse. Line 11 - G91 X-0.1 Y-0.2 - an end point given incrementally - a straight G01.)
G21 G90 G17 G00 X10. Y0. Z5.
G01 F300.
G03.2 X11.173 Y0.4063 I-10. J0. R10.
G02.2 X10. Y0. I-11.173 J-0.4063 R10.
G91 G01 X-0.1 Y-0.2
M30
