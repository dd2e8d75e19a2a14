(G74 and G75 peck cycles - GSK980TDi help text G74 and G75, steps 1-7.)
(G74 from X20 Z1 - face grooves from X20 to X14 stepping P4000 = 4 mm on the diameter = 2 mm radius,)
(pecks Q3000 = 3 mm with the back-off R0.5 of the first block, to Z-5, relief R1 = 1 mm diameter = 0.5 radius.)
(Grooves at X20, X16, X14 - the last step is cut short at Af. At each, Z 1 - 3 = -2, back to -1.5, -5;)
(then relief X + 1 toward the start - none at the first groove - and Z rapid out to Z1, X rapid over to the next.)
(Finally X rapid back to X20.)
G97 S600 M03
G99 G0 X20 Z1
G74 R0.5
G74 X14 Z-5 P4000 Q3000 R1 F0.1
(G75 from X42 Z-10 - grooves from Z-10 to Z-14 stepping Q2500 = 2.5 mm, pecks P2000 = 2 mm diameter = 1 mm radius,)
(no back-off - no first block - to X36. Grooves at Z-10, Z-12.5, Z-14; relief R0.3 in Z toward the start.)
G0 X42 Z-10
G75 X36 Z-14 P2000 Q2500 R0.3 F0.05
G0 X60 Z10
M30
