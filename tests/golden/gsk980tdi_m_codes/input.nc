O0198 (GSK980TDi - the help text's second spindle and spindle positioning M codes)
(Hand check - help text M24/25 - second spindle position or speed control - M50-58 - spindle positioning cancelled or to point n - M63/64/65 - second spindle forward, reverse, stop. Machine functions without a tool motion: accepted with no warning and no record; the first spindle's state stays - 800 rpm.)
G98 M03 S800
M24
M25
M51
M50
M63
M64
M65
G00 X20. Z2.
M30
