(expect NCS-E41 line 4 col 1 on gsk980tdi)
(G32.1 needs the servo spindle in position mode - help text G32.1 note 1 - M14 first.)
G00 X30 Z5
G32.1 W-20 F2 S500 C90
M30
