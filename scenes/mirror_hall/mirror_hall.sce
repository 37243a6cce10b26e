# Two facing mirrors repeat a torus and two spheres; depth bounds the echoes.
camera   1.2 1.6 5.5   0 0.7 -0.5   0 1 0   50   600 400
depth    6
background 0 0 0
ambience 0.1 0.1 0.1

light    0 4 3      0.6 0.6 0.6
light    2 2 -2     0.3 0.25 0.2
light   -2 3 1      0.2 0.25 0.3

plane   -2.5 0 0   1 0 0    0.05 0.05 0.05  0.1 0.1 0.1  0 0 0  1   0.85
plane    2.5 0 0  -1 0 0    0.05 0.05 0.05  0.1 0.1 0.1  0 0 0  1   0.85
plane    0 0 0     0 1 0    0.15 0.15 0.15  0.5 0.45 0.4 0 0 0  1   0
mesh torus.off PHONG        0.2 0.05 0.05   0.8 0.2 0.15 0.9 0.9 0.9 90 0.2
sphere  -1 0.45 -1.2  0.45  0.05 0.1 0.2    0.2 0.4 0.9  0.8 0.8 0.8 120 0.3
sphere   1.1 0.3 0.6  0.3   0.1 0.2 0.05    0.3 0.8 0.2  0.5 0.5 0.5 60  0
