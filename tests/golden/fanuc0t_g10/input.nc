O0600 (FANUC 0-T - G10 P sets the tool offsets, G10 L2 the work offsets - 5002 LGT=0 LWM=0)
(setup.toml - reference X300 Z200 - no offsets - the programme writes them.)
G10 P10001 X-150. Z-80.
(Geometry of offset 1 - X-150 Z-80 as written - X a diameter.)
G10 P1 X0.2 Z-0.1
G10 P1 U0.1
(Wear of offset 1 - X0.2 Z-0.1 - then U adds 0.1 - X0.3.)
G10 L2 P1 Z-400.
(G54 Z-400 - the tool stays at machine Z200 - it reads Z600.)
T0101
(The geometry shifts - reads X450 Z680 - the wear moves - a rapid to there - machine X300.3 Z199.9.)
G00 X50. Z5.
(Machine X-99.7 Z-475.1.)
M30
