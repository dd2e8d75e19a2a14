%
O0001(FURA€AO) ; (CRLF, BOM, Latin-1 in a comment)
g0x10z5;g1w-1.f100 (two blocks on one line; lower case)
/G0 X99 (block delete switch off: executed)
N99999 G1 U-2 F[25.4/10]
M30
%
