O0310 (FANUC 0-M - G31 skip and G27 reference point return check - setup.toml, the reference point at machine zero)
(Hand check - G54 puts X0 Y0 Z0 at machine X-400 Y-300 Z-351 with the external offset.)
G21 G17 G90 G54
G00 X0 Y0 Z10.
(G31 - a feed to X20 at F200 that a skip signal would end - none comes - warning NCS-W34 - machine X-380.)
G31 X20. F200.
(G91 G28 Z0 - Z to the reference point, machine Z0 - programme Z351.)
G91 G28 Z0
(G27 Z351. - already there - the check passes, no move.)
G90 G27 Z351.
(G27 X400. Y300. - a rapid to machine X0 Y0 - the reference point - the check passes.)
G27 X400. Y300.
M30
