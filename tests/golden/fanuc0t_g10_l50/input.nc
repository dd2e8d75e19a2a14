O0353 (FANUC 0-T - G10 L50 programmable parameter input, up to G11)
(Hand check - FANUC 0i manual, G10 L50 - N the parameter number, R its value, P the axis for an axis parameter; a bit parameter as eight binary digits.)
G10 L50
(5130 - the G92 thread chamfer in 0.1 lead - 10 to 20 - 2 leads; 5131 - its angle - 0 = 45 degrees - kept.)
N5130 R20
G11
G00 X30. Z5. M03 S500
(G92 F2. - the chamfer 2 x 2 = 4 mm at 45 degrees - from Z-16. to X28. at Z-20. - half the 8 mm of X20. to X28. is 4 mm radial.)
G92 X20. Z-20. F2.
G10 L50
N5130 R0
G11
(No chamfer now - straight to Z-20.)
G92 X20. Z-20.
G00 X40.
M30
