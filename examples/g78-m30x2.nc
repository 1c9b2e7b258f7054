O0078 (G78: M30x2, degressive depth, radial infeed, two finishing passes)
G00 X35 Z5
G78 P1060 Q100 R0.05 D2
G78 X27.4 Z-30 P1300 Q400 F2
G00 X100 Z100
M30
