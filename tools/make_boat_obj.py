#!/usr/bin/env python3
"""Writes a low-poly closed boat hull as OBJ (assets/scenes/meshes/boat.obj, the floating body of
assets/scenes/dam_break_3d_floating.json).

The hull is the convex hull of three stations: a flat transom at the stern (x = -L/2), the widest
section at the shoulder (x = L/5) and the stem at the bow (x = L/2), each a deck edge of beam B at
y = +H/2 over a keel edge of beam B/2 at y = -H/2 (the stem's both on z = 0, its foot set back).
Along x, its deck up (+y), centred on its bounding box. Every face is a convex polygon of the hull,
fanned into triangles counter-clockwise seen from outside, every edge shared by two of them (the
solver refuses open meshes). Usage: make_boat_obj.py OUT.obj [L B H]
"""
import itertools
import math
import sys


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def hull_faces(points, eps=1e-9):
    """The convex hull's faces, each a list of point indices counter-clockwise seen from outside."""
    centre = tuple(sum(p[k] for p in points) / len(points) for k in range(3))
    planes = []
    for i, j, k in itertools.combinations(range(len(points)), 3):
        n = cross(sub(points[j], points[i]), sub(points[k], points[i]))
        length = math.sqrt(dot(n, n))
        if length < eps:
            continue
        n = tuple(x / length for x in n)
        d = dot(n, points[i])
        if dot(n, centre) > d:
            n, d = tuple(-x for x in n), -d
        if all(dot(n, p) <= d + eps for p in points) and not any(
                abs(dot(n, m) - 1) < 1e-6 and abs(d - e) < 1e-6 for m, e in planes):
            planes.append((n, d))
    faces = []
    for n, d in planes:
        on = [i for i, p in enumerate(points) if abs(dot(n, p) - d) < 1e-7]
        c = tuple(sum(points[i][k] for i in on) / len(on) for k in range(3))
        u = sub(points[on[0]], c)
        u = tuple(x / math.sqrt(dot(u, u)) for x in u)
        v = cross(n, u)
        on.sort(key=lambda i: math.atan2(dot(sub(points[i], c), v), dot(sub(points[i], c), u)))
        faces.append(on)  # counter-clockwise about the outward normal n
    return faces


def boat(L, B, H):
    top, bottom = H / 2, -H / 2
    points = []
    for x, beam in ((-L / 2, B), (L / 5, B)):
        points += [(x, top, -beam / 2), (x, top, beam / 2), (x, bottom, -beam / 4), (x, bottom, beam / 4)]
    points += [(L / 2, top, 0.0), (L / 2 - L / 8, bottom, 0.0)]
    lo = [min(p[k] for p in points) for k in range(3)]
    hi = [max(p[k] for p in points) for k in range(3)]
    mid = [(a + b) / 2 for a, b in zip(lo, hi)]
    return [tuple(p[k] - mid[k] for k in range(3)) for p in points]


def main():
    if len(sys.argv) not in (2, 5):
        sys.exit(__doc__)
    L, B, H = (0.24, 0.12, 0.06) if len(sys.argv) == 2 else tuple(float(a) for a in sys.argv[2:5])
    points = boat(L, B, H)
    triangles = []
    for face in hull_faces(points):
        triangles += [(face[0], face[i], face[i + 1]) for i in range(1, len(face) - 1)]
    edges = {}
    for t in triangles:
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            edges[(a, b)] = edges.get((a, b), 0) + 1
    assert all(n == 1 and edges.get((b, a)) == 1 for (a, b), n in edges.items()), "not closed"
    with open(sys.argv[1], "w") as out:
        out.write("# boat hull L=%g B=%g H=%g, %d triangles, made by tools/make_boat_obj.py\n" % (L, B, H, len(triangles)))
        for p in points:
            out.write("v %.6f %.6f %.6f\n" % p)
        for t in triangles:
            out.write("f %d %d %d\n" % tuple(i + 1 for i in t))


if __name__ == "__main__":
    main()
