(G54.1 P1-P48 - additional work systems - FANUC 0i-MF - docs/setup.md.)
(Line 6 - G54 X0 Y0 Z10 - machine X-100 Y-50 Z-190. Line 7 - G54.1 P1 - the same programme point - machine X-300.)
(Line 8 - #7001 reads P1's X - -300 - line 9 - G10 L20 P2 X-410. - line 10 - G54.1 P2 X0 Y0 - machine X-410 Y-80 - Z not given stays at machine Z-190 - Z60 in P2.)
(Line 11 - X to the value #7001 read plus 300 - 0 - no move.)
G21 G90 G17
G54 G00 X0 Y0 Z10.
G54.1 P1 X0 Y0
#100 = #7001
G10 L20 P2 X-410.
G54.1 P2 X0 Y0
G00 X[#100 + 300]
M30
