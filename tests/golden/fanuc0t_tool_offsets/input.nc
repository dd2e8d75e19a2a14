O0400 (FANUC 0-T T offsets, 5002 LGT=0 LWM=0 - geometry shifts the coordinates, wear moves in the T block)
(setup.toml - offset 1 geometry X-150 Z-80 wear X0.2 Z-0.1 - offset 2 geometry X-160 Z-90 wear Z0.3 - X as diameters)
(Hand check - machine = programme + geometry + wear; work offsets 0.)
G00 X100. Z50.
(No offset - machine X100 Z50.)
T0101
(The geometry shifts - the tool reads X250 Z130 - the wear moves it by X0.2 Z-0.1 - a rapid from X249.8 Z130.1 to X250 Z130 - machine X100.2 Z49.9.)
G00 X50. Z5.
(Absolute - the tip at X50 Z5 - machine X-99.8 Z-75.1.)
T0202
(Geometry X-10 Z-10 shifts - reads X60 Z15 - wear X-0.2 Z0.4 moves - machine X-100 Z-74.7.)
U-10. W-5.
(Incremental right after T - from X60 Z15 to X50 Z10 - offset-dependent - machine X-110 Z-79.7.)
G28 U0 W0
(FANUC keeps the offset at G28 - reference X300 Z200 is programme X460 Z289.7.)
G00 X60. Z20.
(Machine X-100 Z-69.7.)
T0200
(Offset cancelled - the geometry shift goes - reads X-100 Z-69.7 - the wear Z0.3 moves back - a rapid to X-100 Z-70.)
G00 X60. Z20.
(No offset - machine X60 Z20.)
T0303
(Offset 3 is not in the setup's table - warning NCS-W32 - taken as 0 - no change, no motion.)
M30
