%
O0001 (SUBPROGRAMMES: M98 P COUNT+NUMBER, M98 P L, NESTING, M99 P)
(Hand check, G17 G90, rapid 10000 mm/min in X, Y and Z on the fanuc0m profile.)
(Line 5: rapid to X0 Y0 Z10 - one record, depth 0.)
G21 G17 G90 G00 X0. Y0. Z10.
(Line 7: P0020100 = count 2, O0100 - FANUC 0i-TB/MB manual 12.3.)
(O0100 lowers Z by 1 - G91 - then calls O0200 once - depth 2 - which feeds X+5 and back.)
(So: Z9 - feed X5 - feed X0 - Z8 - feed X5 - feed X0, the Z moves at depth 1, the feeds at depth 2.)
M98 P0020100
(Line 11: P0300 L1 - the FANUC 0-M form - O0300 moves Y to 20 and returns to N40 here - GSK980TDi help text M99 P.)
(N30 - X99 - is passed over; N40 goes to X-10, its record carries n 40. Times: each 5 mm feed at F500 takes 0.65 s - 0.6 s plus the profile's acceleration.)
M98 P0300 L1
N30 G00 X99.
N40 G00 X-10.
M30
O0100
G91 G00 Z-1.
G90 M98 P0200
M99
O0200
G01 X5. F500.
X0.
M99
O0300
G00 Y20.
M99 P40
N10 G00 Y99.
M99
%
