(Hand check - G32.3 W-10 R10 from X10 Z-15 - radius 5 - to X10 Z-25 - counter-clockwise seen)
(from +Y. Chord 10 along Z, so the centre is sqrt[100 - 25] = 8.660 below the chord middle -)
(Z-20, radius 5 - 8.660 = -3.660, diameter -7.321. Start and end are at 60 and 120 degrees from)
(the Z axis, inside the sector around +X - Z is the long axis - seed 002 note 1. 10 mm of Z at)
(2 x 200 = 400 mm/min is 1.5 s.)
(Seed 002 code example. The manual shows it without a feed for the G1 block, as an excerpt of)
(a longer programme: F100 on the first line is ncsight's addition so that G1 can move.)
(Times - the hand figures above are at constant speed - each move adds its time constant, 100 ms for a rapid, 50 ms for a feed or a thread run - docs/guide.md.)
G98 F100
G1 X10 Z-15
M15
M03 S200
G32.3 W-10 F2 R10
M30
