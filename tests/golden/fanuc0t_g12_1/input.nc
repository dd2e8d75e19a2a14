O0121 (FANUC 0-T - G12.1/G13.1 polar coordinate interpolation - a flat milled on the face with the C axis)
(Hand check - FANUC 0i-T manual - in G12.1 the programme is Cartesian in X - a diameter - and the hypothetical C - a length; the machine makes it with X at radius r = sqrt[x^2 + c^2] and C at the angle atan2[c, x]; F is the speed along the programmed path. ncsight records pieces - each within 0.001 mm of the path - of an X feed with the C turn made with it.)
G98 G00 X40. Z2. C0.
G01 Z-2. F100.
G12.1
(To X20. at C0 - radius 20 to 10 - a radial feed, no turn - 10 mm - 3 s + 0.05.)
G01 X20. F200.
(C-8. - along the flat x = 10 - r from 10 to 12.806, C from 0 to -38.660 degrees - 8 mm - 2.4 s; each move accelerates once - 0.05 s.)
C-8.
(C8. - back across - C to +38.660 through 0 - 16 mm - 4.8 s.)
C8.
(X40. - out to x = 20 at c = 8 - r 21.541, C 21.801 degrees - 10 mm - 3 s.)
X40.
(G13.1 - the machine is at X43.081 and C21.801 - the next block starts there.)
G13.1
G00 Z10.
M30
