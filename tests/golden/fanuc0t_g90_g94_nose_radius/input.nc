O0710 (FANUC 0-T - G90 and G94 in nose radius compensation - offset by the imaginary tool nose 3, R0.8 - setup.toml)
(Hand check - the cycle's in, cut and out moves are compensated on the side the tip puts the nose centre - right of a -Z cut, left of a -X facing cut - whatever G41/G42 say; records are the imaginary tip.)
T0101
G99 G97 S800 M03
G0 X50. Z2.
G42
(Straight G90 - in to X40 with the nose touching Z2, tip Z1.2 - the cut on X40 to Z-20 exactly - out ends perpendicular, tip X48.4 - back to X50 Z2.)
G90 X40. Z-20. F0.2
(Taper G90 R-2 from X36 Z2 to X40 Z-20 - the start perpendicular to the taper - centre Z2.0724 X18.7967 radius - tip X35.9934 Z1.2724 - the inner corner with the face out - centre Z-19.2 X20.7305 - tip X39.8611 Z-20.)
G90 X40. Z-20. R-2.
G0 X50. Z2.
(G94 facing - in along Z to the face Z-2, tip X48.4 - the cut on Z-2 to X20 - out ends perpendicular, tip Z1.2 - back.)
G94 X20. Z-2. F0.2
G40 G0 X100. Z100.
M30
