# A Menger sponge of level 2 (400 cubes): neighbours' faces are coplanar,
# and rays pass through its tunnels.
camera   3.4 2.6 4.2   0 0.9 0   0 1 0   40   480 360
depth    1
background 0.05 0.05 0.08
ambience 0.15 0.15 0.15

light    6 8 5     0.7 0.65 0.6
light   -5 3 6     0.3 0.3 0.4

mesh  sponge.off FLAT   0.15 0.1 0.1   0.8 0.45 0.3   0.3 0.3 0.3   30   0
plane 0 0 0   0 1 0    0.2 0.2 0.2     0.5 0.5 0.5   0 0 0   1    0.2
