# No lights and depth 0: only ambient colour, so no shadow or reflection rays.
camera   0 1.5 6   0 0.8 0   0 1 0   45   320 240
background 0.1 0.1 0.1
ambience 1 1 1

sphere  -1.2 0.8 0  0.8   0.8 0.3 0.2   1 1 1   1 1 1   10  0.5
cylinder 1.2 0.8 0  0.5  0 1 0  1.6   0.2 0.5 0.8   1 1 1   1 1 1   10  0
plane 0 0 0  0 1 0   0.3 0.3 0.3   1 1 1   0 0 0   1  0
