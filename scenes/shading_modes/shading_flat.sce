# Coarse meshes shaded FLAT; shading_phong.sce shows the same meshes the other way.
camera   0 3.2 8.5   0 0.8 0   0 1 0   40   640 400
depth    0
background 0.08 0.09 0.12
ambience 0.15 0.15 0.15

light   -6 8 6    0.7 0.7 0.7
light    6 5 4    0.4 0.4 0.5

#    file           mode   ambient        diffuse        specular       shin  mirror
mesh icosphere.off  FLAT  0.3 0.1 0.1    0.8 0.25 0.2   0.6 0.6 0.6    40    0
mesh torus.off      FLAT  0.1 0.2 0.3    0.2 0.5 0.8    0.7 0.7 0.7    60    0
mesh floor.off      FLAT   0.2 0.2 0.2    0.55 0.55 0.5  0 0 0          1     0
