(FANUC 0-T G83 and G87 without Q - the format of a FANUC lathe manual, see docs/commands/g83_g87_lathe.md.)
(G83 from X0 Z5.: initial level Z5, R-3. puts the R level at Z2: rapid to Z2, feed to Z-20., dwell P500 = 0.5 s,)
(rapid back to the initial level Z5. The next block gives only a bottom: the same again to Z-25.;)
(then W-10. - from the R level - drills to Z-8.)
(G87 from X30. Z-10.: the initial level is X30 - radius 15 -, R-2. a radius: the R level is radius 13 - X26 -;)
(feed to X10., rapid back to X30.)
G99 M03 S1000
G00 X0 Z5.
G83 Z-20. R-3. P500 F0.1
Z-25.
W-10.
G80
G00 X30. Z-10.
G87 X10. R-2. F0.1
G80
M30
