(expect PS0118 line 3 col 1 on fanuc0m)
(Five levels including function brackets - FANUC alarm 118 - six here.)
#1 = [[[[[SIN[1]]]]]]
M30
