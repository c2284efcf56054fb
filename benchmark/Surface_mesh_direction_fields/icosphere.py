#!/usr/bin/env python3
"""Writes the unit icosphere: the icosahedron's faces split in four LEVELS
times, new vertices pushed onto the sphere. A mesh without obtuse triangles
(no negative cotangent weight), the control of multigrid_eigen_experiment.

    icosphere.py LEVELS > sphere.off      (LEVELS 6: 40,962 vertices)
"""
import math
import sys


def icosahedron():
    t = (1 + 5 ** 0.5) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
              (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    return [on_sphere(p) for p in points], faces


def on_sphere(p):
    r = math.sqrt(sum(x * x for x in p))
    return tuple(x / r for x in p)


def split(points, faces):
    """Each face in four; each edge's midpoint made once."""
    midpoint_of = {}

    def midpoint(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoint_of:
            points.append(on_sphere([(points[a][i] + points[b][i]) / 2 for i in range(3)]))
            midpoint_of[key] = len(points) - 1
        return midpoint_of[key]

    finer = []
    for a, b, c in faces:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    return finer


def main():
    if len(sys.argv) != 2 or not sys.argv[1].isdigit():
        sys.exit("usage: icosphere.py LEVELS > sphere.off")
    points, faces = icosahedron()
    for _ in range(int(sys.argv[1])):
        faces = split(points, faces)
    out = ["OFF", f"{len(points)} {len(faces)} 0"]
    out += [f"{x!r} {y!r} {z!r}" for x, y, z in points]
    out += [f"3 {a} {b} {c}" for a, b, c in faces]
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
