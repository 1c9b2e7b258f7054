O0079 (G78: the same M30x2 with equal depth and alternating flank infeed, screw-in E0.3)
G00 X35 Z5
G78 P0360 Q50 R0.1 D1 E0.3
G78 X27.4 Z-30 P1300 Q300 F2
G00 X100 Z100
M30
