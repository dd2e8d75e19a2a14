O0320 (FANUC 0-M - G60 single direction positioning - overruns X 2 mm from the minus side, Y 1 mm from the plus side, by the args)
(Hand check - each moving axis goes first to its overrun point before the end, then to the end.)
G21 G17 G90 G00 X0. Y0. Z10.
(To X20 Y10 - via X18 Y11 - X from below, Y from above.)
G60 X20. Y10.
(Back to X5 Y-10 - via X3 Y-9 - the same sides whatever the direction of travel.)
G60 X5. Y-10.
(Z does not move - no overrun on it; X only - via X8.)
G60 X10.
M30
