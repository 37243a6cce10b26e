camera 0 0 0 0 0 -1 0 1 0 45 2 2
# comment only
depth 100000
