O12345678 (Eight-digit programme numbers - the 0i-F's option - a setting here - docs/commands/m98_m99.md.)
(Line 4 - M98 P12345679 L2 - O12345679 twice - each W-1. - then line 5.)
G98 G00 X10. Z0
M98 P12345679 L2
G00 X30.
M30
O12345679
G00 W-1.
M99
