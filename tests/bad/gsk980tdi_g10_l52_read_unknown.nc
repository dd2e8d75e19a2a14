(expect NCS-E38 line 4 col 1 on gsk980tdi)
(No.1 is not a parameter ncsight models - its value cannot be read into #100.)
G10 L52
N1 R100
G11
M30
