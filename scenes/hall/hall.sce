# A hall of 40 x 16 x 8 m seen from inside: floor stripes, windowed walls
# with bars, beams, columns and stairs. Every part is a box of long, thin
# triangles; the sun shines in through the windows.
camera   2 1.7 18   -1.5 2.6 -12   0 1 0   70   480 360
depth    1
background 0.55 0.7 0.9
ambience 0.18 0.18 0.2

light    60 30 -5    0.8 0.75 0.65
light    0 7 4       0.35 0.35 0.38

mesh hall.off FLAT   0.25 0.24 0.22   0.7 0.66 0.6   0.2 0.2 0.2   20   0.12
