(Every drilling cycle of seed 003 in the G17 plane - holes in XY, drilling along Z.)
(Initial level Z30 - R Z3 - bottom Z-6. Q2 pecks - G73 backs up d = 0.5 - 531 - G83 returns to R, then down to 0.3 above - 532.)
(G76 and G87 shift Q1.5 along -X - parameter 2 bit 4 = 1 - after an oriented stop. G87 backs up from R Z-6 to Z3.)
G21 G17 G90 G00 X0. Y0. Z30.
S800 M03
G98 G81 X10. Y10. Z-6. R3. F120.
G99 G82 X20. P250
G98 G73 X30. Q2.
G83 X40.
G76 X50. Q1.5
G85 X60.
G86 X70.
G87 X80. R-6. Z3.
G88 X90. R3. Z-6. P100
G89 X100.
G80
M05
S500 M04
G98 G74 X110. Z-6. R3. F625.
M03
G84 X120.
G80 M30
