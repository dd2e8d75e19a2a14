O0100 (GSK980TDi: G54-G59, G52, G50, G28 and G30 P2 with a machine setup - setup.toml)
(Hand check, X as a diameter: machine = programme + work + G50 shift + G52 local.)
(Power on at the reference point X200 Z100, in G54 - programme X200 Z400.)
G00 X50 Z10
(G54 - machine X50 Z-290.)
G55 G00 X50 Z10
(G55 - the tool reads Z60, then Z10 - machine Z-340.)
G52 Z5
G00 Z0
(G52 Z5 - local zero at Z5 of G55 - Z0 is machine Z-345.)
G52 W0
(G52 W0 - U and W act as X and Z in G52, help text G52 - the local system is cancelled, the tool reads Z5.)
G54 G50 X100 Z20
(G50 with G54 in one block - G54 is void, help text G54-G59 note 6 - still G55; the tool reads X100 Z20 - shift X-50 Z-15.)
G00 Z0
(Z0 in G55 with the shift is machine Z-365 - had G54 taken effect it would be Z-315.)
G54 G00 X100 Z20
(G54 with the shift - the tool reads X100 Z-50 - X100 Z20 is machine X50 Z-295.)
G28 U0 W0
(G28 U0 W0 - the intermediate point is the start - to the reference point X200 Z100, programme X250 Z415.)
G30 P2 U0 W0
(G30 P2 - to the 2nd reference point X150 Z50 - programme X200 Z365.)
M30
