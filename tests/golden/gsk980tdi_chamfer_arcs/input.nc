O0195 (GSK980TDi - the chamfer function next to arcs - line to arc, arc to line, line to line, arc to arc)
(Hand check - help text, chamfer function 1-4 - the corner arc D is tangent to both moves - its centre D inside both - the chamfer L - type I - joins two points equally far from the corner - by chord on an arc - L apart.)
G98 G00 X20. Z2.
G01 Z0 F100
(Line to arc - Z-10. D2. then G03 X40. Z-20. R10. - the arc about Z-20 r10 leaves the corner Z-10 r10 along +X - a right turn. The centre D inside both - r 12 and 12 from the arc's centre - [z + 20] squared = 144 - 4 - z -8.1678. Tangent points - Z-8.1678 X20 on the line - on the arc 10/12 of the way to the centre - Z-10.1399 r11.6667 X23.3333 - clockwise.)
Z-10. D2.
(Arc to line - L2. then G01 X50. - the arc ends along -Z - the line goes +X. Found by halving - a X39.8128 Z-18.635 on the arc - 10 from its centre - b X42.7364 Z-20 on the line - each a chord 1.3682 from the corner - 2 apart - dz 1.365 dr 1.4618.)
G03 X40. Z-20. R10. L2.
(Line to line - D3. - a square corner turning left - ends 3 from the corner - X44 Z-20 and X50 Z-23 - centre X44 Z-23 - counter-clockwise.)
G01 X50. D3.
Z-30.
(Arc to arc - G02 about Z-30 r35 then G02 about Z-40 r45 - D2 - the centre 12 from both - Z-41.8557 r33.1443 - tangent points 10/12 of the way from each centre - X66.9072 Z-39.8797 and X70.2406 Z-41.5464 - counter-clockwise.)
G02 X70. Z-40. R10. D2.
G02 X90. Z-50. R10.
G00 X100.
M30
