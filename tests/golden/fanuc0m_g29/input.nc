O0290 (FANUC 0-M - G29 return from the reference point through the intermediate point of the last G28 or G30)
(Hand check - FANUC 0i manual, G29 - each axis G29 names goes at rapid to the intermediate point the last G28/G30 gave it, then to the point given; machine = programme + G54 or G55.)
G21 G17 G90 G54 G00 X10. Y10. Z50.
(G91 G28 Z0. - the intermediate point Z50 - the tool there already - then to the reference point, programme Z350.)
G91 G28 Z0.
(G28 X20. Y30. - the intermediate point X20 Y30, kept for X and Y - reference point programme X400 Y300.)
G90 G28 X20. Y30.
(G29 X40. Y50. - rapid to X20 Y30, then to X40 Y50; Z stays at 350.)
G29 X40. Y50.
(G29 Z20. - Z through its intermediate point Z50 to Z20.)
G29 Z20.
(G30 Y40. - to Y40, then the 2nd reference point, machine Y-100 - programme Y200; Y's intermediate point is now 40.)
G30 Y40.
(G91 G29 X5. Y-10. - incremental from the intermediate points - X20 + 5 = X25, Y40 - 10 = Y30 - through X20 Y40.)
G91 G29 X5. Y-10.
(G55 - 100 mm further in X - the tool reads X-75; the intermediate point stays X20 of the new system, as the manual says - G29 X0 goes through X20 of G55.)
G90 G55
G29 X0.
M30
