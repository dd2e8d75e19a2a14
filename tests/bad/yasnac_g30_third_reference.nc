(expect NCS-E33 line 3 col 5 on yasnac-lx3)
(ncsight takes the YASNAC LX3 G30 to the 2nd reference point only, docs/setup.md.)
G30 P3 U0 W0
M30
