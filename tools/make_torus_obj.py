#!/usr/bin/env python3
"""Writes a closed triangle torus as OBJ (assets/scenes/meshes/torus.obj, the mesh of assets/scenes/mesh_pool_3d.json).

The torus lies in the xz plane (its hole along y), centred at the origin: major radius R (centre of
the tube), minor radius r, `major` segments around and `minor` around the tube. Faces are
counter-clockwise seen from outside, every edge shared by two of them (the solver refuses open
meshes). Usage: make_torus_obj.py OUT.obj [R r major minor]
"""
import math
import sys


def torus(R, r, major, minor):
    vertices, faces = [], []
    for i in range(major):
        u = 2 * math.pi * i / major
        for j in range(minor):
            v = 2 * math.pi * j / minor
            ring = R + r * math.cos(v)
            vertices.append((ring * math.cos(u), r * math.sin(v), ring * math.sin(u)))
    index = lambda i, j: (i % major) * minor + (j % minor) + 1  # OBJ counts from 1
    for i in range(major):
        for j in range(minor):
            a, b, c, d = index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)
            faces += [(a, d, c), (a, c, b)]
    return vertices, faces


def main():
    if len(sys.argv) not in (2, 6):
        sys.exit(__doc__)
    R, r, major, minor = (0.1, 0.035, 32, 12) if len(sys.argv) == 2 else (
        float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5]))
    vertices, faces = torus(R, r, major, minor)
    with open(sys.argv[1], "w") as out:
        out.write("# torus R=%g r=%g, %d x %d segments, made by tools/make_torus_obj.py\n" % (R, r, major, minor))
        for v in vertices:
            out.write("v %.6f %.6f %.6f\n" % v)
        for f in faces:
            out.write("f %d %d %d\n" % f)


if __name__ == "__main__":
    main()
