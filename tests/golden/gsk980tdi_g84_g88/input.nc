(G84 and G88 rigid tapping after M29 S_ - GSK980TDi help text G84/88, steps 1-6.)
(M29 S300, then G84 from X0 Z3: tap to Z-15 with the spindle at +300 rpm - F1.5, right-hand -, dwell P200 = 0.2 s,)
(tap back to Z3 at -300 rpm. 18 mm = 12 turns: the way out starts at spindle angle 0.)
(Z-20: again from Z3; 23 mm = 15 1/3 turns, so the way out starts at 360 - 120 = 240 degrees.)
(G80 ends the mode. M29 S200, G88 from X40 - radius 20 - to X20: F-1 is left-hand - the spindle turns -200 going in.)
G97 M03 S500
G00 X0 Z3
M29 S300
G84 Z-15 P200 F1.5
Z-20
G80
G00 X40 Z-10
M29 S200
G88 X20 F-1
G80
M30
