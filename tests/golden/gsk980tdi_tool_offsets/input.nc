O0402 (GSK980TDi T offsets - tool traverse mode, the ncsight default - G28 cancels the offset, help text G28 note 2)
(setup.toml - offset 1 geometry X-150 Z-80 wear X0.2 Z-0.1 - offset 2 geometry X-160 Z-90 wear Z0.3 - X as diameters)
(Hand check - machine = programme + geometry + wear; work offsets 0. The display keeps the programmed point.)
G00 X100. Z50.
(No offset - machine X100 Z50.)
T0101
(The whole offset moves in the T block - the tip of tool 1 goes from X249.8 Z130.1 to X100 Z50 - machine X-49.8 Z-30.1.)
G00 X50. Z5.
(Machine X-99.8 Z-75.1.)
T0202
(The difference X-10.2 Z-9.6 moves - the tip back to X50 Z5 - machine X-110 Z-84.7.)
U-10. W-5.
(To X40 Z0 - machine X-120 Z-89.7.)
G28 U0 W0
(To the reference X300 Z200 - the offset is cancelled - the tool reads X300 Z200.)
G00 X60. Z20.
(No offset any more - machine X60 Z20 - FANUC would be at X-100 Z-69.7.)
T0200
(Nothing left to cancel - no motion.)
G00 X60. Z20.
M30
