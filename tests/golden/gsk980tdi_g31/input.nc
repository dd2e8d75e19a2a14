O0311 (GSK980TDi - G31 skip with the signal P1 - help text G31)
(Hand check - no skip signal in a simulation - warning NCS-W34 - the feed runs to W-10 at F100.)
G98 G00 X40. Z5.
G31 W-10. F100 P1
M30
