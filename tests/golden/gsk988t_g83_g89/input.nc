(GSK988T - G80, G83-G89 as the FANUC 0-T has them - inferred: the GSK988T follows FANUC numbering and its drilling page was not at hand - docs/commands/g83_g87_lathe.md - 5101 bit 2 = 0: the high-speed peck, back off 5114 = 0.5 mm.)
(G83 from X0 Z5. - R-3. puts the R level at Z2 - Q4. is 4 mm a peck: feed to Z-2., back to Z-1.5, feed to Z-6., back to Z-5.5, feed to Z-10., back to Z-9.5, feed to Z-12.)
(then dwell P500 = 0.5 s and rapid to the initial level Z5.)
(G87 from X40. Z-10. - initial level radius 20, R-3. a radius: R level radius 17 = X34 - Q3. 3 mm a peck on the radius: X28, back to X29, X22, X23, X16, X17, X10 - rapid back to X40.)
(G84 from X0 Z5. - R-2.: the R level Z3 - feed to Z-10. at F1.0 per revolution = 1000 mm/min at S1000 - the spindle reversed - feed back to Z3 - the spindle forward - rapid to Z5.)
(G85 - R level Z3 - feed to Z-8. at 0.05 = 50 mm/min - dwell 0.2 s - feed back to Z3 - rapid to Z5.)
(G88 and G89 from X40. Z-20. - initial level radius 20 - R-2.: R level X36 - G88 to X20. and out with the spindle reversed - G89 to X24. - dwell 0.3 s - feed out to X36 - rapid to X40.)
G99 G97 S1000 M03
G00 X0. Z5.
G83 Z-12. R-3. Q4. P500 F0.1
G80
G00 X40. Z-10.
G87 X10. R-3. Q3. F0.1
G80
G00 X0. Z5.
G84 Z-10. R-2. F1.0
G85 Z-8. R-2. P200 F0.05
G80
G00 X40. Z-20.
G88 X20. R-2. F1.0
G89 X24. R-2. P300 F0.05
G80 M05
M30
