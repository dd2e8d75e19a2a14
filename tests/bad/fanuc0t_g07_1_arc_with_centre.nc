(expect PS0022 line 6 col 16 on fanuc0t)
(An arc in cylindrical interpolation takes R - FANUC 0i-T manual - not I, J or K.)
G98 G00 X44. Z5. C0
G19 G07.1 C20.
G01 X36. F100.
G02 Z-10. C30. K-5.
M30
