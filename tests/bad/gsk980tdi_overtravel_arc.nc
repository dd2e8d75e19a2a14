(expect NCS-E77 line 6 col 1 on gsk980tdi)
(Both ends of the arc are inside the travel; its top, X 2 x [100 + 40] or 280 as a diameter, is not.)
G00 X200 Z40
G01 X200 Z0 F100
(A half circle G03 from Z0 to Z-80 about X200 Z-40, radius 40: it bulges to X280.)
G03 X200 Z-80 R40
M30
