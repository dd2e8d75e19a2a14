(The tool and work offsets as system variables - memory C - FANUC layout as recalled - docs/commands/macros.md.)
(Offset 1 - geometry X100 as a diameter - R0.8 - tip 3 - wear X0.2 - Z-0.05. G54 Z-200. No T word - no offset moves the tool.)
(Line 7 - X to #2701 - the X geometry - 100. Line 8 - Z to #2901 times 100 - 80. Line 9 - X to #2301 times 10 - the tip 3 - 30.)
(Line 10 - X to #2001 times 100 - the X wear 0.2 - 20. Line 11 - Z to #2101 times 1000 - -50. Line 12 - Z to #5222 plus 300 - G54 Z - 100.)
(Lines 13 and 14 - #2001 = #2001 + 0.1 and #5222 = -190. - the tool stays on the machine - Z now 90 - line 15 - X to #10001 times 100 - 30 - Z to #5222 plus 290 - 100 - the machine Z -90.)
G00 X0 Z0
G00 X#2701
G00 Z[#2901 * 100]
G00 X[#2301 * 10]
G00 X[#2001 * 100]
G00 Z[#2101 * 1000]
G00 Z[#5222 + 300]
#2001 = #2001 + 0.1
#5222 = -190.
G00 X[#10001 * 100] Z[#5222 + 290]
M30
