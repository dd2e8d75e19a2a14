(expect NCS-E46 line 4 col 1 on fanuc0i-tf)
(R-30. from the initial level Z5. puts the R level at Z-25. - beyond the hole bottom Z-20. - the drill would cut backward)
G98 G00 X0 Z5.
G83 Z-20. R-30. F100.
G80
M30
