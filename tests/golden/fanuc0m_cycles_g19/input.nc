(Every drilling cycle of seed 003 in the G19 plane - holes in YZ, drilling along X.)
(Initial level X30 - R X3 - bottom X-6. Q2 pecks - G73 backs up d = 0.5 - 531 - G83 returns to R, then down to 0.3 above - 532.)
(G76 and G87 shift Q1.5 along -Y - parameter 2 bit 4 = 1 - after an oriented stop. G87 backs up from R X-6 to X3.)
G21 G19 G90 G00 Y0. Z0. X30.
S800 M03
G98 G81 Y10. Z10. X-6. R3. F120.
G99 G82 Y20. P250
G98 G73 Y30. Q2.
G83 Y40.
G76 Y50. Q1.5
G85 Y60.
G86 Y70.
G87 Y80. R-6. X3.
G88 Y90. R3. X-6. P100
G89 Y100.
G80
M05
S500 M04
G98 G74 Y110. X-6. R3. F625.
M03
G84 Y120.
G80 M30
