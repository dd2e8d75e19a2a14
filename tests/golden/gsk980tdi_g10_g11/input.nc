O0352 (GSK980TDi - G10 L3 tool life lines and G10 L52 parameter reading and writing, each up to G11)
(Hand check - help text G10 L3 - the lines up to G11 are data - no motion, their words ignored - warning NCS-W12 - ncsight keeps no tool life.)
G10 L3
P0001 L500 Q1
T0101
G11
(Help text, parameter reading and writing - N the number, W the value written, R the macro variable read into - R100 is #100.)
G10 L52
(No.19 - the thread pull-out in 0.1 lead - read into #100 - its default 10 - then written 15 and read into #101.)
N19 R100
N19 W15
N19 R101
(No.18 - a bit parameter - W01000000 sets bit 6 - read back into #102 as its binary digits - 1000000.)
N18 W01000000
N18 R102
G11
(The G92 pulls out over 1.5 x 2 = 3 mm - from Z-17, to X26 at Z-20 - as No.19 = 15 says.)
G00 X30 Z5 M03 S500
G92 X20 Z-20 F2
(X is 10 x [15 - 10] = X50; Z is 1000000 / 100000 = Z10.)
G00 X[[#101 - #100] * 10] Z[#102 / 100000]
M30
