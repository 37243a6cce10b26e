# A (2,3) torus knot of 106,496 triangles over a slightly mirrored floor.
camera   0 2.4 7   0 1.2 0   0 1 0   38   560 420
depth    2
background 0.02 0.02 0.04
ambience 0.12 0.12 0.12

light    5 8 6     0.75 0.7 0.65
light   -6 4 3     0.25 0.3 0.4

mesh  knot.off PHONG   0.2 0.15 0.05   0.85 0.6 0.2   0.8 0.8 0.8   80   0.05
plane 0 0 0   0 1 0    0.2 0.2 0.2     0.35 0.35 0.38 0 0 0         1    0.35
