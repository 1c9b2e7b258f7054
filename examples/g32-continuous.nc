O0033 (GSK G32: continuous thread, straight then taper, run-out J2 K3 on the last block)
G00 X60 Z5
X39.2
G32 Z-20 F2
X43.2 Z-35 J2 K3
G00 X60
Z5
X38.6
G32 Z-20 F2
X42.6 Z-35 J2 K3
G00 X60
Z5
M30
