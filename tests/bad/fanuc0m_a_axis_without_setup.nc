(expect PS0009 line 3 col 5 on fanuc0m)
(A 4th axis A without a setup that declares it: the FANUC 0-M has X, Y and Z)
G91 A45.
M30
