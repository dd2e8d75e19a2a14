O0401 (FANUC 0-T T offsets, 5002 LGT=1 LWM=1 - geometry and wear move the tool, with the next move)
(setup.toml - offset 1 geometry X-150 Z-80 wear X0.2 Z-0.1 - offset 2 geometry X-160 Z-90 wear Z0.3 - X as diameters)
(Hand check - machine = programme + geometry + wear; work offsets 0. The display keeps the programmed point.)
G00 X100. Z50.
(No offset - machine X100 Z50.)
T0101
(No motion in the T block - the offset moves with the next move.)
G00 X50. Z5.
(Absolute - the tip at X50 Z5 whatever the offset - machine X-99.8 Z-75.1 - as with LGT=0.)
T0202
U-10. W-5.
(Incremental - counts from the display X50 Z5 - the tip ends at X40 Z0 - machine X-120 Z-89.7 - not X50 Z10 as with LGT=0.)
G28 U0 W0
(The reference X300 Z200 is programme X460 Z289.7.)
G00 X60. Z20.
(Machine X-100 Z-69.7.)
T0200
(The cancel moves with the next move.)
G00 X60. Z20.
(No offset - machine X60 Z20.)
M30
