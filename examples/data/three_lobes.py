"""Writes three_lobes.csv, a gap file for creepwork solve --gap: a wheel on a
rail touching in three places across the rail. Each lobe is a Hertzian gap
x^2 / (2 Rx) + (y - yc)^2 / (2 Ry) lifted by dh above the datum h = 0;
the gap is the smallest of the three. All lengths in metres."""

nx, ny = 31, 57                # cells along x (rolling) and y (across)
dx, dy = 0.4e-3, 0.5e-3        # cell size [m]
x0, y0 = -6e-3, -14e-3         # centre of cell (0, 0) [m]
lobes = [(-9e-3, 0.0), (0.0, 4e-6), (9e-3, 10e-6)]  # (yc, dh) [m]: centre across, lift

with open("three_lobes.csv", "w") as f:
    f.write("x_m,y_m,h_m\n")
    for j in range(ny):
        for i in range(nx):
            x, y = x0 + i * dx, y0 + j * dy
            h = min(x * x / 0.9 + (y - yc) * (y - yc) / 0.4 + dh for yc, dh in lobes)
            f.write("%.9g,%.9g,%.9g\n" % (x, y, h))
