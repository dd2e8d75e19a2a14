(expect NCS-E33 line 4 col 5 on gsk980tdi)
(No.18 is a bit parameter - its value is binary digits - W2 is not - help text, parameter reading and writing, note 1.)
G10 L52
N18 W2
G11
M30
