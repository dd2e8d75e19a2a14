O0182 (GSK980TDi - the chamfer function - L a chamfer, D a corner arc between two G01 moves)
(Hand check - help text, chamfer function - the corner between a block's move and the next gets a straight chamfer [L] or an arc tangent to both [D]; No.181.0 = 0 - type I - L is the chamfer's length.)
G98 G00 X0 Z2
G01 Z0 F100
(X20 L2 - the face up to radius 10, then -Z: a square corner; type I - each end 2 / sqrt 2 = 1.4142 from the corner: X17.1716 Z0 to X20 Z-1.4142 - 2 mm - 1.2 s + 0.05.)
X20 L2
(Z-20 D3 - -Z then +X: a square corner turning clockwise - the arc's ends 3 tan 45 = 3 from the corner: X20 Z-17 to X26 Z-20, centre X26 Z-17.)
Z-20 D3
X40 L2
(The last move has no corner: made whole.)
Z-30
G00 X50
M30
