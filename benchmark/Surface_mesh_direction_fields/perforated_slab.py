#!/usr/bin/env python3
"""Writes a closed surface of high genus as OFF: the perforated slab of the tests' make_perforated_slab()
(generated_meshes.h): (2 h + 1)^2 unit cubes one thick without those at odd positions (h^2 holes, genus h^2),
each square cut into m x m pairs of triangles, then six steps of uniform Laplacian smoothing
(halfway to the neighbours' mean).
  usage: perforated_slab.py HOLES_PER_SIDE M OUT.off"""
import sys

import numpy as np


def slab(holes, m):
    cells = 2 * holes + 1

    def solid(i, j, k):
        return k == 0 and 0 <= i < cells and 0 <= j < cells and not (i % 2 == 1 and j % 2 == 1)

    index, points, faces = {}, [], []

    def at(g):
        g = tuple(g)
        if g not in index:
            index[g] = len(points)
            points.append([c / m for c in g])
        return index[g]

    for ci in range(cells):
        for cj in range(cells):
            for axis in range(3):
                for side in (0, 1):
                    cell = [ci, cj, 0]
                    nxt = list(cell)
                    nxt[axis] += 1 if side == 1 else -1
                    if not solid(ci, cj, 0) or solid(*nxt):
                        continue
                    u, w = (axis + 1) % 3, (axis + 2) % 3

                    def grid(i, j):
                        g = [0, 0, 0]
                        g[axis] = (cell[axis] + side) * m
                        g[u] = cell[u] * m + i
                        g[w] = cell[w] * m + j
                        return at(g)
                    for i in range(m):
                        for j in range(m):
                            p00, p10, p11, p01 = grid(i, j), grid(i + 1, j), grid(i + 1, j + 1), grid(i, j + 1)
                            if side == 0:
                                p10, p01 = p01, p10
                            faces += [(p00, p10, p11), (p00, p11, p01)]
    V, F = np.array(points, dtype=np.float64), np.array(faces, dtype=np.int64)
    neighbours = [set() for _ in range(len(V))]
    for a, b, c in F:
        neighbours[a].update((b, c))
        neighbours[b].update((a, c))
        neighbours[c].update((a, b))
    rows = np.repeat(np.arange(len(V)), [len(n) for n in neighbours])
    cols = np.concatenate([sorted(n) for n in neighbours])
    counts = np.array([len(n) for n in neighbours], dtype=np.float64)
    for _ in range(6):
        summed = np.zeros_like(V)
        np.add.at(summed, rows, V[cols])
        V = 0.5 * V + 0.5 * summed / counts[:, None]
    return V, F


def main():
    holes, m, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    V, F = slab(holes, m)
    with open(out, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in V)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in F)
    print(f"{out}: genus {holes * holes}, {len(V)} vertices, {len(F)} faces")


if __name__ == "__main__":
    main()
