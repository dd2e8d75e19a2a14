O0500 (FANUC 0-M - G43 G44 G49 with H, G10 L2 and G10 L10 L11 changing the tables for the blocks after them)
(setup.toml - G54 X-400 Y-300 Z-350 - offset 1 length 100 wear -0.5 - power on at machine 0 0 0.)
(Hand check - machine Z = programme Z + G54 Z + the length in force.)
G21 G17 G90 G54
G00 X0 Y0 Z100.
(No length - machine Z-250.)
G43 Z50. H1
(G43 H1 adds 99.5 - the tip at Z50 - machine Z-200.5.)
G01 Z10. F200.
(Machine Z-240.5.)
G49 G00 Z100.
(G49 - machine Z-250.)
G10 L2 P1 Z-300.
(G54 Z is now -300 - the tool stays - it reads Z50.)
G00 Z100.
(Machine Z-200.)
G10 L10 P2 R120.
G91 G10 L11 P2 R-1.
(Offset 2 - length 120, and G91 adds -1 to its wear - 119 in all.)
G90 G44 Z20. H2
(G44 subtracts - machine Z 20 - 300 - 119 = -399.)
G43 H1
(H alone in G43 - the difference moves as a rapid - from the new tip Z-198.5 to Z20 - machine Z-180.5.)
G49
(G49 alone moves the 99.5 back - machine Z-280.)
M30
