O0385 (GSK980TDi - G85 end face and G89 side boring cycles - inferred - the help text names them only)
(Hand check - as the GSK980TDi's own G83/G87 - from the start point, no R level - and the FANUC G85/G89 - feed in, dwell P, feed out: rapid to the hole position, feed to the bottom, dwell P ms, feed back to the start.)
G99 G00 X0 Z5 M03 S500
(G85 Z-10 P500 F0.1 - at 0.1 x 500 = 50 mm/min - 15 mm in - 18 s + 0.05 - 0.5 s - 15 mm out.)
G85 Z-10 P500 F0.1
G80
G00 X40 Z-20
(G89 X20 F0.05 - 25 mm/min - radius 20 to 10 - 10 mm - 24 s + 0.05 each way, no dwell.)
G89 X20 F0.05
G80
M30
