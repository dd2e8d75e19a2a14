(expect NCS-E33 line 4 col 19 on gsk988t)
(GSK988TA/TB manual, G92: J cannot be less than 0; its direction comes from the start point)
G0 X44 Z5 M03 S500
G92 X38.5 Z-20 F2 J-1
M30
