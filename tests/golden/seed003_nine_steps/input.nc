(Seed 003 worked example, the manual's blanks filled in. Numbers are the table's steps.)
(Hand check - initial level Z50 - G98 at power on - each hole - XY rapid at the current level, rapid to R, feed to Z, back.)
(2 - G81 with Z R F and K2 - under G90 the same hole is drilled twice.)
(3 - Y20 - a new hole with the same data - K is not modal, so once.)
(4 - G82 - new mode, Z R F kept, P500 = 0.5 s dwell at the bottom.)
(5 - G80 with X Y - the cycle ends, the move is G00 - group 01 in force - and R Z P are cleared, F kept.)
(6 - G85 - Z and R must be given again - feed out to R, then rapid to the initial level - G98.)
(7 - X Z - a hole at X50 with the new Z-10.)
(8 - G89 - R and P from 6, Z from 7 - dwell, feed out to R, rapid up.)
(9 - G01 - group 01 ends the cycle - the move is a G01 feed at the F kept since 2.)
(Times - the hand figures above are at constant speed - each move adds its time constant, 100 ms for a rapid, 50 ms for a feed or a thread run - docs/guide.md.)
G21 G17 G90 G00 X0. Y0. Z50.
S1000 M03
G81 X10. Y10. Z-5. R2. F100. K2
Y20.
G82 X20. P500
G80 X30. Y30.
G85 X40. Y40. Z-8. R2. P300
X50. Z-10.
G89 X60. Y60.
G01 X70. Y70.
M30
