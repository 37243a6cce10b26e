# the small meshes, a scene mesh and mirrors
camera 0 2 6  0 0.5 0  0 1 0  45 24 16
depth 3
ambience 0.1 0.1 0.1
light 4 6 4  0.8 0.8 0.8
light -3 2 5  0.3 0.3 0.4
plane 0 0 0  0 1 0  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0.5
sphere -1.5 0.5 0  0.5  0.2 0.2 0.2  0.6 0.3 0.3  0.5 0.5 0.5  30 0.6
mesh octahedron_crlf.off PHONG 0.2 0.2 0.2 0.6 0.5 0.4 0.3 0.3 0.3 20 0.3
mesh grid.off FLAT 0.2 0.2 0.2 0.4 0.4 0.6 0 0 0 1 0.4
mesh copies.off PHONG 0.2 0.2 0.2 0.6 0.6 0.2 0.3 0.3 0.3 20 0
mesh ../../scenes/everything/icosphere.off PHONG 0.1 0.05 0.2 0.5 0.3 0.8 0.7 0.7 0.7 80 0.1
