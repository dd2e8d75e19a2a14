(expect NCS-E38 line 4 col 1 on fanuc0i-tf)
(G49 is taken on the 0i-TF - nothing is in force to cancel - G43 - the mill-turn option's tool length compensation - is not simulated yet)
G40 G49 G80
G43 H1 Z5.
M30
