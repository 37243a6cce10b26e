# The camera inside a closed room of 3,072 triangles, lit from inside.
camera   -3.2 2.6 3.4   0.4 1.0 -0.6   0 1 0   70   560 420
depth    1
background 1 0 1
ambience 0.15 0.15 0.15

light    0 4.2 0     0.55 0.55 0.5
light    3 1.5 3     0.3 0.25 0.2

mesh room.off  FLAT    0.3 0.3 0.3   0.7 0.68 0.62  0 0 0        1    0
mesh torus.off PHONG   0.1 0.2 0.2   0.2 0.6 0.6    0.8 0.8 0.8  60   0.25
sphere -1.4 0.7 -1.8 0.7   0.2 0.1 0.1   0.7 0.3 0.3   0.6 0.6 0.6  40  0
cylinder 2.2 2.5 -2.6  0.4  0 1 0  5.0   0.1 0.1 0.2   0.3 0.3 0.7   0.4 0.4 0.4  20  0
