#!/usr/bin/python3
"""Loop subdivision of a triangle mesh (OFF in, OFF out), to make the larger meshes of the benchmark from the
shared ones (each step: four times the faces). Interior rules of Loop (1987); on the boundary, edge points are
midpoints and boundary vertices stay (enough for cost measurements). --midpoint splits each triangle in four
at its edges' midpoints instead: the same piecewise-linear surface, finer (for the spectra of a mesh and of its
refinement, README.md).
  usage: loop_subdivide.py IN.off OUT.off [STEPS] [--midpoint]"""
import sys

import numpy as np


def read_off(path):
    with open(path) as f:
        words = f.read().split()
    assert words[0] == "OFF", "an OFF file"
    nv, nf = int(words[1]), int(words[2])
    V = np.array(words[4:4 + 3 * nv], dtype=np.float64).reshape(nv, 3)
    F = np.array(words[4 + 3 * nv:4 + 3 * nv + 4 * nf], dtype=np.int64).reshape(nf, 4)
    assert (F[:, 0] == 3).all(), "triangles only"
    return V, F[:, 1:]


def subdivide(V, F, midpoint=False):
    nv = len(V)
    half = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])       # (3 |F|, 2) directed sides
    opposite = np.concatenate([F[:, 2], F[:, 0], F[:, 1]])                  # the corner facing each side
    key = np.minimum(half[:, 0], half[:, 1]) * nv + np.maximum(half[:, 0], half[:, 1])
    edges, edge_of_side, count = np.unique(key, return_inverse=True, return_counts=True)
    a, b = edges // nv, edges % nv
    border = count == 1
    far = np.zeros((len(edges), 3))
    np.add.at(far, edge_of_side, V[opposite])
    edge_points = np.where(border[:, None] | midpoint, 0.5 * (V[a] + V[b]), 0.375 * (V[a] + V[b]) + 0.125 * far)
    # vertex points: (1 - k beta) v + beta sum of neighbours; boundary vertices stay
    valence = np.bincount(np.concatenate([a, b]), minlength=nv).astype(np.float64)
    neighbours = np.zeros_like(V)
    np.add.at(neighbours, a, V[b])
    np.add.at(neighbours, b, V[a])
    on_border = np.zeros(nv, dtype=bool)
    on_border[a[border]] = True
    on_border[b[border]] = True
    beta = np.where(valence == 3, 3.0 / 16.0, 3.0 / (8.0 * np.maximum(valence, 1)))
    moved = (1 - valence * beta)[:, None] * V + beta[:, None] * neighbours
    vertex_points = np.where(on_border[:, None] | (valence == 0)[:, None] | midpoint, V, moved)
    m = nv + edge_of_side.reshape(3, len(F)).T                                 # (|F|, 3): edge point of each side
    x, y, z = F[:, 0], F[:, 1], F[:, 2]
    e01, e12, e20 = m[:, 0], m[:, 1], m[:, 2]
    faces = np.concatenate([np.stack([x, e01, e20], 1), np.stack([e01, y, e12], 1),
                            np.stack([e20, e12, z], 1), np.stack([e01, e12, e20], 1)])
    return np.concatenate([vertex_points, edge_points]), faces


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        np.savetxt(f, V, fmt="%.17g")
        np.savetxt(f, np.hstack([np.full((len(F), 1), 3), F]), fmt="%d")


def main():
    midpoint = "--midpoint" in sys.argv
    args = [a for a in sys.argv[1:] if a != "--midpoint"]
    V, F = read_off(args[0])
    for _ in range(int(args[2]) if len(args) > 2 else 1):
        V, F = subdivide(V, F, midpoint)
    write_off(args[1], V, F)
    print("%s: %d vertices, %d faces" % (args[1], len(V), len(F)))


if __name__ == "__main__":
    main()
