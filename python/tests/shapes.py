"""Analytic meshes the module's tests share: (V, F) as numpy arrays."""
import math

import numpy as np


def octahedron():
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=np.float64)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return V, F


def sphere(levels=3):
    V, F = octahedron()
    points, faces = [tuple(p) for p in V], [tuple(f) for f in F]
    for _ in range(levels):
        middle, new = {}, []
        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = np.add(points[a], points[b]) / 2
                points.append(tuple(p / np.linalg.norm(p)))
                middle[key] = len(points) - 1
            return middle[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = new
    return np.array(points), np.array(faces, dtype=np.int64)


def torus(n=24, m=12, R=1.0, r=0.4):
    V = np.array([[(R + r * math.cos(2 * math.pi * j / m)) * math.cos(2 * math.pi * i / n),
                   (R + r * math.cos(2 * math.pi * j / m)) * math.sin(2 * math.pi * i / n),
                   r * math.sin(2 * math.pi * j / m)] for i in range(n) for j in range(m)])
    F = []
    for i in range(n):
        for j in range(m):
            a, b, c, d = i * m + j, ((i + 1) % n) * m + j, ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            F += [(a, b, c), (a, c, d)]
    return V, np.array(F)
