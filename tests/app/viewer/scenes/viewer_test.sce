# The viewer's snapshot scene: a PHONG ball, a FLAT mirror box, a sphere and
# a floor, two lights, one reflection. Small, so snapshots render quickly.
camera 0 2.2 5.5  0 0.55 0  0 1 0  45  240 160
depth 1
background 0.15 0.2 0.3
ambience 0.2 0.2 0.2
light 3 5 4  0.8 0.8 0.8
light -4 3 2  0.3 0.25 0.2
mesh ball.off PHONG  0.1 0.1 0.1  0.8 0.25 0.2  0.6 0.6 0.6  40 0
mesh box.off FLAT  0.1 0.1 0.1  0.2 0.5 0.3  0.3 0.3 0.3  20 0.4
sphere 0.2 0.35 1.4  0.35  0.1 0.1 0.1  0.2 0.3 0.8  0.8 0.8 0.8  60 0.2
plane 0 0 0  0 1 0  0.1 0.1 0.1  0.6 0.6 0.55  0 0 0  1 0.15
