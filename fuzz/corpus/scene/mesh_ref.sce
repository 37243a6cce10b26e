camera 2 2 4  0.5 0.5 0.5  0 1 0  50 16 16
light 3 5 4  1 1 1
mesh tetra.off PHONG 0.1 0.1 0.1 0.5 0.5 0.5 0 0 0 1 0
mesh cube_quads.off FLAT 0.1 0.1 0.1 0.5 0.5 0.5 0.3 0.3 0.3 10 0.2
