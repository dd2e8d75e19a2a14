(GSK988T: M14 puts the servo spindle in position mode, M15 back to speed mode, seed 001 O0009)
M14
G00 X30.14 Z3
M03 S500
G98 G01 W-10 F100
M05
M15
M30
