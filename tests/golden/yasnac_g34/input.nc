O0341 (YASNAC LX3 - G34 variable-lead thread cutting, inferred from the FANUC 0-T - E the lead as in the LX3's G92)
(Hand check - as tests/golden/fanuc0t_g34 - E2. K1. over W-6. - revolution 1 at 2.5 mm to Z-2.5, revolution 2 at 3.5 mm to Z-6.)
G00 X30. Z0. S200 M03
G34 W-6. E2. K1.
G00 X40.
M30
