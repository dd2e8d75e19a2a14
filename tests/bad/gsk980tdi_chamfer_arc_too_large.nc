(expect NCS-E89 line 4 col 1 on gsk980tdi)
(D50 - the corner arc between the line and an arc of radius 5 - its centre 50 inside both - r60 and 55 from the arc centre Z-15 r10 - lies at z 7.9 - its tangent point before the line starts at Z2 - help text, chamfer function, case 2.)
G98 G00 X20. Z2.
G01 Z-10. F100 D50.
G03 X30. Z-15. R5.
M30
