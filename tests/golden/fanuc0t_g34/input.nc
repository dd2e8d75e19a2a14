O0340 (FANUC 0-T - G34 variable-lead thread cutting - F the lead at the start, K its change per revolution)
(Hand check - the lead grows continuously - K per revolution - so revolution n is cut at the mean lead F + K[n - 1/2]; one record per revolution, each from the block's start angle.)
G00 X40. Z4. S300 M03
X29.
(Z4 to Z-4 - 8 mm - F2. K2. - revolution 1 at 3 mm to Z1., revolution 2 at 5 mm to Z-4. - 2 revolutions at 300 rpm - 0.2 s each, the first with the 0.05 s acceleration.)
G34 Z-4. F2. K2.
G00 X40.
Z4.
X28.4
(Decreasing - F5. K-0.5 from Z4. to Z-10. - 14 mm - means 4.75, 4.25, 3.75 - to Z-0.75, Z-5., Z-8.75 - then the last 1.25 mm, recorded at the fourth revolution's mean lead 3.25 - ncsight's record of a part revolution: the lead there runs from 3.5 to about 3.31.)
G34 Z-10. F5. K-0.5
G00 X40.
M30
