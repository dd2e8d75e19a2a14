(Every drilling cycle of seed 003 in the G18 plane - holes in ZX, drilling along Y.)
(Initial level Y30 - R Y3 - bottom Y-6. Q2 pecks - G73 backs up d = 0.5 - 531 - G83 returns to R, then down to 0.3 above - 532.)
(G76 and G87 shift Q1.5 along -Z - parameter 2 bit 4 = 1 - after an oriented stop. G87 backs up from R Y-6 to Y3.)
G21 G18 G90 G00 Z0. X0. Y30.
S800 M03
G98 G81 Z10. X10. Y-6. R3. F120.
G99 G82 Z20. P250
G98 G73 Z30. Q2.
G83 Z40.
G76 Z50. Q1.5
G85 Z60.
G86 Z70.
G87 Z80. R-6. Y3.
G88 Z90. R3. Y-6. P100
G89 Z100.
G80
M05
S500 M04
G98 G74 Z110. Y-6. R3. F625.
M03
G84 Z120.
G80 M30
