(expect NCS-E36 line 4 col 1 on yasnac-lx3)
G97 S300 M03
G00 X80. Z80.8
G92 X70. I-1.5 F2.
M30
