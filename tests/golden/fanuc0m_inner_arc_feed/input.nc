O0199 (FANUC 0-M - the feed inside an arc in cutter compensation)
(Hand check - FANUC 0i-M and 16i manuals, internal circular cutting feedrate change - the cutter centre inside an arc runs at F x Rc / Rp so that the programmed path keeps F - at least parameter 1710 per cent. D1 radius 5 - setup.toml.)
G21 G17 G90 G00 X0 Y0 Z5.
G01 Z-2. F200.
(G41 X20. - the start-up ends perpendicular to the circle's start - left of +Y - at X15 Y0.)
G41 G01 X20. Y0 D1
(A full circle CCW about X0 Y0 - radius 20 - the cutter on its left - inside - centre path radius 15 - F200 x 15 / 20 = F150 - 2 pi 15 / 150 min = 37.7 s.)
G03 X20. Y0 I-20. J0
G40 G01 X0 Y0
G00 Z5.
M30
