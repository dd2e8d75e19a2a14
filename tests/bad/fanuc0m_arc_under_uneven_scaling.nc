(expect NCS-E38 line 5 col 1 on fanuc0m)
(An arc under scaling with other magnifications on X and Y would be an ellipse: not simulated)
G51 X0 Y0 I2000 J1000 K1000
G01 X10. Y0 F100.
G02 X0 Y10. R10.
M30
