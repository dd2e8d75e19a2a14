(expect NCS-E52 line 2 col 1 on fanuc0m)
$BR0137.MIN%
NAT00 G85 N0207 D7 F0.4 U0.4 W0.1
M02
