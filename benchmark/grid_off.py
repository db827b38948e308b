#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes an ASCII OFF of the smooth height field z = 0.1 sin(3x) cos(2y) + 0.05 x y over
[0, 1]^2: an N x N grid, two triangles a cell, CCW seen from +z, coordinates with 9
significant digits. With `flip`, the middle face has two indices swapped: one inconsistently
oriented face, which the tool's soup repair fixes.

  grid_off.py N PATH [clean|flip]
"""
import math
import sys


def main():
    n, path = int(sys.argv[1]), sys.argv[2]
    flip = len(sys.argv) > 3 and sys.argv[3] == "flip"
    h = 1.0 / (n - 1)
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (n * n, 2 * (n - 1) * (n - 1)))
        lines = []
        for j in range(n):
            y = j * h
            for i in range(n):
                x = i * h
                z = 0.1 * math.sin(3 * x) * math.cos(2 * y) + 0.05 * x * y
                lines.append("%.9g %.9g %.9g\n" % (x, y, z))
            if len(lines) > 100000:
                out.write("".join(lines))
                lines = []
        out.write("".join(lines))
        lines = []
        middle = (n - 1) * (n - 1)
        face = 0
        for j in range(n - 1):
            for i in range(n - 1):
                a = j * n + i
                b, c, d = a + 1, a + n, a + n + 1
                for f in ((a, b, d), (a, d, c)):
                    if flip and face == middle:
                        f = (f[1], f[0], f[2])
                    lines.append("3 %d %d %d\n" % f)
                    face += 1
            if len(lines) > 100000:
                out.write("".join(lines))
                lines = []
        out.write("".join(lines))


if __name__ == "__main__":
    main()
