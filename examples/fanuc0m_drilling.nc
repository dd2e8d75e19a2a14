O1000 (FANUC 0-M: four holes with G81, two with peck drilling G83, one tapped with G84)
(Lengths carry a decimal point: without one a FANUC 0-M reads 0.001 mm.)
G21 G17 G40 G49 G80 G90
G0 X0. Y0. Z50.
S1200 M03
G99 G81 X20. Y20. Z-12. R3. F150. (drill to Z-12, back to the R point)
X60.
Y60.
G98 X20. (the last hole returns to the initial level Z50)
G80
G99 G83 X40. Y40. Z-30. R3. Q6. F120. (pecks of 6 mm, clearance by parameter 532)
G98 X80. Y40.
G80
S500 M03
G98 G84 X40. Y80. Z-15. R5. F625. (M10x1.25: F = 1.25 x 500)
G80
G0 Z100.
M05
M30
