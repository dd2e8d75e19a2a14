(expect NCS-E05 line 2 col 1 on gsk980tdi)
GO X0.
M30
