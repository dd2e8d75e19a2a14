(G74 and G75 peck cycles - GSK980TDi help text G74 and G75, steps 1-7.)
(G74 from X20 Z1 - face grooves from X20 to X14 stepping P4000 - the text moves X by Di/2, 2 mm radius = 4 on the diameter -,)
(pecks Q3000 = 3 mm with the back-off R0.5 of the first block, to Z-5, relief R1 - Dd/2 = 0.5 radius.)
(Grooves at X20, X16, X14 - the last step is cut short at Af. At each, Z 1 - 3 = -2, back to -1.5, -5;)
(then the relief X + 1 on the diameter toward the start's side - the first groove too, as the steps say -,)
(Z rapid out to Z1, X rapid over to the next groove. Finally X rapid back to X20.)
G97 S600 M03
G99 G0 X20 Z1
G74 R0.5
G74 X14 Z-5 P4000 Q3000 R1 F0.1
(G75 from X42 Z-10 - grooves from Z-10 to Z-14 stepping Q2500 = 2.5 mm, pecks P2000 = 2 mm radius - step 1 has no /2 -,)
(to X36 = 3 mm radius deep - pecks to X38, back 0.5 - the back-off e is one value for G74 and G75 - to X39, then X36.)
(Grooves at Z-10, Z-12.5, Z-14; relief R0.3 in Z toward the start at each, X out to X42, Z over to the next.)
G0 X42 Z-10
G75 X36 Z-14 P2000 Q2500 R0.3 F0.05
G0 X60 Z10
M30
