(expect NCS-E44 line 4 col 1 on gsk980tdi)
M3 S300
G0 X65 Z5
G92 X40 Z5 F3
M30
