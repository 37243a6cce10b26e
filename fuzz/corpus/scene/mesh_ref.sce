camera 0 0 5 0 0 0 0 1 0 60 16 16
light 1 1 1 1 1 1
mesh missing.off PHONG 0.1 0.1 0.1 0.5 0.5 0.5 0 0 0 1 0
