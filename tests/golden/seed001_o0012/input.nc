(Seed 001 example O0012 on gsk988t - G92.1 with S300, J3 K1 on every block - the same path as)
(seed 000's G92 - rapid to X58.7 Z5, thread to Z-27, pull-out K1 J3 to X64.7 Z-28, rapid)
(X65 Z-28, rapid X65 Z5 - the pull-out is within the retract distance 3.15 mm - note 11.)
O0012;
G0 X150 Z50 T0101; (螺纹刀)
G0 X65 Z5; (快速定位)
M14; (主轴切换到位置方式)
G92.1 X58.7 Z-28 F3 S300 J3 K1; (加工螺纹，分 4 刀切削，第一次进刀 1.3mm)
X57.7 J3 K1 ; (第二次进刀 1mm)
X57 J3 K1; (第三次进刀 0.7mm)
X56.9 J3 K1; (第四次进刀 0.1mm)
M15; (主轴切换到速度方式)
M30;
