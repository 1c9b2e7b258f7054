(Renhe: G30 spiral tail U10 W2 on a metric G33, then G30 alone: the standard tail on a second G33)
G00 X50 Z10
G30 U10 W2
G00 U-16
G33 W-40 F1.5
G00 U6
W40
G30
G01 U-10 F150
G33 W-50 F2
G00 U12.4
W50
M30
