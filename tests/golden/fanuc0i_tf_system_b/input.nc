O0001 (G-code system B - 3401#6 GSB - docs/profiles.md)
(Line 5 - G92 sets the position X100 Z100 and clamps the spindle at 2000 rpm - line 6 - G95 feed per revolution - F0.2 at S800 is 160 mm/min.)
(Line 8 - G77 is system A's G90 - the turning cycle to X35 Z-20 - line 9 repeats it at X30.)
(Line 11 - G78 is system A's G92 - the thread cycle - 1.5 lead - chamfer 5130 - 1 lead - at 45 degrees.)
G92 X100. Z100. S2000
G95 G97 S800 M03
G90 G00 X40. Z2.
G77 X35. Z-20. F0.2
X30.
G00 X40. Z5.
G78 X38. Z-15. F1.5
X37.5
(Line 14 - G91 - incremental - W5 moves Z by 5 - U and W stay the incremental words too - inferred.)
G91 G00 U0 W5.
G90 G00 X100. Z100.
M30
