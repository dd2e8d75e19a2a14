O0300 (FANUC 0-M: G54-G59, G52, G92, G53, G28 and G30 with a machine setup - setup.toml)
(Hand check, machine = programme + external + work + G92 shift + G52 local; external Z-1.)
(Power on at the reference point, machine 0 0 0, in G54 - programme X400 Y300 Z351.)
G21 G17 G90 G40 G49 G80
(G54 origin X-400 Y-300 Z-351 - machine X-400 Y-300 Z-341.)
G54 G00 X0 Y0 Z10.
(G55 origin X-200 - the tool stays, now at programme X-200 - then to X0 Y0 - machine X-200.)
G55 X0 Y0
(G52 X10 Y5 - the local zero at X10 Y5 of G55 - no motion; X0 Y0 is machine X-190 Y-295.)
G52 X10. Y5.
X0 Y0
(G52 X0 Y0 cancels - the tool reads X10 Y5 again.)
G52 X0 Y0
(G92 - the tool now reads X0 Y0 Z0 - shift X10 Y5 Z10 on every work system.)
G92 X0 Y0 Z0
(X5 - machine X-185 Y-295 Z-341.)
G01 X5. F100.
(Back to G54 with the shift - origin X-390 Y-295 Z-341 - the tool reads X205.)
G54 G00 X0 Y0
(G53 Z0 - machine Z0, programme Z341; G53 is for this block only.)
G53 Z0
(G91 G53 - incremental - ignored with warning NCS-W30 - X0 moves nothing.)
G91 G53 X0
(G91 G28 X0 Y0 - the intermediate point is where the tool is - home X0 Y0 is programme X390 Y295.)
G28 X0 Y0
(G30 via programme X5 Y0 absolute to the 2nd reference point X-250 Y-100 - programme X140 Y195.)
G90 G30 P2 X5. Y0
(G30 P3 - the setup has no reference_3 - warning NCS-W31, taken as machine zero - from the intermediate point X5 Y0 to X390 Y295.)
G30 P3 X5. Y0
M30
