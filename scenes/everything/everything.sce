# Every entity of the format: spheres, a plane, open cylinders and a mesh,
# with coloured lights, a mirror sphere and ambience.
camera   0 2.2 6.5   0 0.7 0   0 1 0   45   600 450
depth    3
background 0.3 0.45 0.7
ambience 0.2 0.2 0.2

light   -4 6 5     0.6 0.5 0.4
light    4 3 5     0.3 0.35 0.5

plane    0 0 0   0 1 0          0.15 0.15 0.15  0.6 0.6 0.6   0 0 0        1    0.15
sphere  -1.6 0.8 0   0.8        0.1 0.1 0.1     0.1 0.1 0.1   1 1 1       200   0.8
sphere   0 0.4 1.6   0.4        0.3 0.1 0.0     0.9 0.3 0.1   0.5 0.5 0.5  50   0
cylinder 0 0.9 -0.6  0.35  0 1 0  1.8           0.1 0.2 0.1  0.3 0.7 0.3  0.6 0.6 0.6  40  0
cylinder -0.2 0.35 1.0  0.2  1 0.2 -0.5  1.2     0.2 0.2 0.0  0.8 0.7 0.1  0.7 0.7 0.7  70  0.2
mesh icosphere.off PHONG        0.1 0.05 0.2    0.5 0.3 0.8   0.7 0.7 0.7  80   0
