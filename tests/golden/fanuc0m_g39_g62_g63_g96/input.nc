O0391 (FANUC 0-M - G39 corner arcs, G62, G63 tapping mode and G96/G97)
(Hand check - FANUC 0i-M manual - G39 between two moves in cutter compensation makes the outer corner an arc of the cutter radius about the corner point; G63 keeps the feed at 100 % and lets FEED HOLD wait for the block's end; G96 S is m/min at the radius of the axis parameter 3770 names - X.)
G21 G17 G90 G00 X-20. Y0 Z5.
G01 Z-2. F200.
(G41 D1 - radius 5 - the start-up to X-5 Y0 - perpendicular to the next move.)
G41 G01 X0 Y0 D1
Y20.
(G39 - the corner at X0 Y20 turns right, away from the cutter - an outer corner: the first move ends at X-5 Y20, an arc clockwise about X0 Y20 to X0 Y25, then along Y25.)
G39
X30.
G39
Y0
G40 X50.
(G62 - automatic corner override - here outside cutter compensation: nothing to slow.)
G62
(G63 - Z-2 to Z-10 at F100 - 8 mm - 4.8 s + 0.05, at any feed override - crates/ncsight/tests/operator.rs runs it at 50 %.)
G63 G01 Z-10. F100.
G64 G00 Z5.
(G96 S100 at X50 - the diameter 100 - 100000 / [pi x 100] = 318.3 rpm; G97 S500 - 500 rpm.)
G96 S100 M03
G01 X20. F100.
G97 S500
(G62 in cutter compensation - an inner corner of at most 91 degrees [1711] on the work side runs at 50 % [1712] from Ls = 1 mm [1714] before it to Le = 1 mm [1713] after it on the cutter centre path. The start-up to X0 Y5 - its corner is not slowed. X40. then Y40. turn left with the cutter on the left - an inner corner of 90 degrees at X35 Y5: X34 to X35 at F100 - 1 mm in 0.6 s - running on from F200 without a stop; Y5 to Y6 at F100; on to Y40 at F200; G40 X50. - Y40 ends perpendicular at X35 Y40.)
G62 G00 X-10. Y-10.
G01 Z-2. F200.
G41 X0 Y0 D1
X40.
Y40.
G40 X50.
G64 G00 Z5.
(G39 I10. J0 - FANUC 16-MC manual - a direction from the corner - +X: Y20. ends at its old vector X-5 Y20 at once, an arc clockwise [G41] about X0 Y20 to the new vector left of +X - X0 Y25; the path goes on from there: X30. meets Y0 at the ordinary corner X35 Y25 - not a start-up.)
G00 X-20. Y0
G01 Z-2. F200.
G41 G01 X0 Y0 D1
Y20.
G39 I10. J0
X30.
Y0
G40 X50.
G00 Z5.
M30
