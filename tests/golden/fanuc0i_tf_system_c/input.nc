O0001 (G-code system C - 3401#7 GSC - docs/profiles.md)
(Line 4 - G71 is metric input - G95 feed per revolution - line 6 - G20 is system A's G90 - the turning cycle.)
(Line 8 - G99 - return to the R level - the G83 from R-1 - Z1 - to Z-10 at F0.1 - 80 mm/min - back to Z1 - not to the initial Z2.)
G71 G95 G97 S800 M03
G90 G00 X40. Z2.
G20 X35. Z-20. F0.2
G00 X42. Z2.
G99 G83 Z-10. R-1. F0.1
G80
G00 X100. Z100.
M30
