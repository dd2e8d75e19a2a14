(YASNAC LX3: lengths without a decimal point are least input increments, 0.001 mm.)
(X80000 is 80 mm diameter; W-5000 is -5 mm. Feed per revolution at power on: F0.3 x 200 rpm.)
G00 X80000 Z5.
M03 S200
G01 W-5000 F0.3
G00 X100. Z100.
M30
