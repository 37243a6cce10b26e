# A broken scene: the sphere's radius is not a number. The viewer must show
# the error with its file and line, and keep running.
camera 0 2 5  0 0.5 0  0 1 0  45  240 160
light 3 5 4  0.8 0.8 0.8
sphere 0 0.5 0  big  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0
