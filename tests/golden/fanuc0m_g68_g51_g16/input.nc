(FANUC 0-M coordinate transforms - docs/commands/g68_g51_g16.md - each block worked out as written, its points then mirrored, scaled, rotated.)
(Line 13 - G68 X10. Y0 R90. - rotation by 90 degrees about X10 Y0 - line 14 - X20 Y0 goes to X10 Y10 - line 15 - G91 X10. is 10 along the rotated X - X10 Y20.)
(Line 16 - G69 and back to X0 Y0. Line 17 - G51.1 X5. - X mirrored about X5 - line 18 - X10 Y5 goes to X0 Y5.)
(Line 19 - G02 X12. Y7. R2. - clockwise about X12 Y5 as written - mirrored - counter-clockwise from X0 Y5 to X-2 Y7 about X-2 Y5.)
(Line 20 - G50.1 X0 ends the mirror image of X. Line 21 - back to X0 Y0.)
(Line 22 - G51 X10. Y10. P2000 - scaling by 2 about X10 Y10 - setting scaling_option=1 - line 23 - X20 Y10 goes to X30 Y10.)
(Line 24 - G02 X30. Y20. R10. - clockwise about X30 Y10 as written - X50 Y30 about X50 Y10 - radius 20. Line 25 - G50 ends the scaling.)
(Line 26 - G16 - polar coordinates - X the radius - Y the angle. Line 27 - G81 X50. Y30. - the hole at 50 cos 30 = 43.3013 - 50 sin 30 = 25.)
(Line 28 - Y150. - X-43.3013 Y25. Line 29 - G91 Y120. - the angle 270 - X0 Y-50.)
(Line 30 - G90 G80 G15 - back to plain words - G00 X0 Y0.)
(Line 31 - G68 X0 Y0 R45000 - the angle without a decimal point is 0.001 degree - 45 degrees - line 32 - X10. Y0 goes to X7.0711 Y7.0711.)
G21 G17 G90 G00 X0 Y0 Z5.
G68 X10. Y0 R90.
G01 X20. Y0 F100.
G91 X10.
G90 G69 G00 X0 Y0
G51.1 X5.
G01 X10. Y5.
G02 X12. Y7. R2.
G50.1 X0
G00 X0 Y0
G51 X10. Y10. P2000
G01 X20. Y10.
G02 X30. Y20. R10.
G50
G16
G81 X50. Y30. Z-5. R2. F100.
Y150.
G91 Y120.
G90 G80 G15 G00 X0 Y0
G68 X0 Y0 R45000
G01 X10. Y0
G69
M30
