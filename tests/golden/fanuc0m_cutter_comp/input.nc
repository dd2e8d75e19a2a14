O0800 (FANUC 0-M - G41 D1 around an outline with inner, outer, sharp and arc corners - setup.toml, radius 2.5)
(Hand check - the cutter centre 2.5 to the left of travel, clockwise around the outside.)
G21 G17 G90 G40 G54
G00 X0 Y-10. Z5.
G01 Z-3. F300.
(Start-up along Y+ - perpendicular to the next move - X-2.5 Y0.)
G41 D1 Y0
(Outer 90 degrees at X0 Y30 - the offsets extended meet at X-2.5 Y32.5.)
Y30.
(Inner corner into the spike - the line Y32.5 meets the spike's offset at X8.1981.)
X10.
(The spike's top - 37 degrees on the work, sharper than 90 - out 2.5 along each edge - X13.4189 Y48.1623, a move to X16.5811 Y48.1623.)
X15. Y45.
(Outer obtuse at X20 Y30 - the spike's offset meets X22.5 at Y30.4057.)
X20. Y30.
(Inner 90 degrees - X22.5 Y17.5.)
Y15.
(Into a tangent arc - no corner.)
X30.
(G02 R10 about X30 Y5 - the cutter outside - radius 12.5 - X42.5 Y5.)
G02 X40. Y5. R10.
(Tangent into Y0 - outer 90 degrees at X40 Y0 - X42.5 Y-2.5.)
G01 Y0
(Cancelled at the end perpendicular - X0 Y-2.5 - then G40 to X-10 Y0.)
X0
G40 X-10.
G00 Z5.
M30
