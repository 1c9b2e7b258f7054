O0092 (Fanuc G92: the textbook M48x2 in five cycles, chamfer by parameter 5130)
G50 X100. Z100.
S300 M03 T0101
G00 X58. Z70.
G92 X47.1 Z13. F2.
X46.5
X45.9
X45.5
X45.4
G00 X100. Z100.
M30
