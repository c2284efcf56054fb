#!/usr/bin/env python3
"""The field of a mesh's points against the field of the mesh (issue 76's
check): for each mesh, the program runs on the mesh (vertex field) and on its
vertices as a point set (.xyz, normals estimated, or given from the mesh with
--given-normals), and this prints the singular counts, the eigenvalues, the
share of directions within 5 degrees where the mesh field's magnitude is
above 10% of its largest (after the one global turn that matches them best:
a smoothest field is defined up to it) and both compute times.

    python3 compare_with_mesh.py --program build/bin/direction_field [--degree 4] MESH.off ...

With --samples N (and --noise S, a fraction of the mean edge length along the
normal), the points are N random samples of the surface (area-weighted)
instead of its vertices, each compared with the mesh field at its nearest
vertex. --field="OPTIONS" passes options to both runs (the aligned fields:
--field="--align curvature --alignment-weight 0.5").
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np


def read_off(path):
    with open(path) as f:
        words = f.read().split()
    assert words[0].upper().endswith("OFF")
    nv, nf = int(words[1]), int(words[2])
    values = words[4:4 + 3 * nv]
    V = np.array(values, dtype=float).reshape(nv, 3)
    faces, at = [], 4 + 3 * nv
    for _ in range(nf):
        k = int(words[at])
        faces.append([int(w) for w in words[at + 1:at + 1 + k]])
        at += 1 + k
    return V, np.array(faces)


def vertex_normals(V, F):
    N = np.zeros_like(V)
    fn = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    for c in range(3):
        np.add.at(N, F[:, c], fn)
    return N / np.maximum(np.linalg.norm(N, axis=1, keepdims=True), 1e-300)


def run(program, args):
    out = subprocess.run([program] + args + ["--json", "--quiet"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def share_within(a, b, normals, n, degrees, counted):
    pa = a - np.sum(a * normals, axis=1, keepdims=True) * normals
    pb = b - np.sum(b * normals, axis=1, keepdims=True) * normals
    turn = n * np.arctan2(np.sum(np.cross(pa, pb) * normals, axis=1), np.sum(pa * pb, axis=1))
    mean = np.sum(np.exp(1j * turn[counted]))
    off = np.abs(np.angle(np.exp(1j * turn) / mean)) / n
    return float(np.mean(off[counted] < math.radians(degrees)))


def random_samples(V, F, count, noise, seed=1):
    rng = np.random.default_rng(seed)
    fn = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    area = 0.5 * np.linalg.norm(fn, axis=1)
    f = rng.choice(len(F), count, p=area / area.sum())
    r1, r2 = np.sqrt(rng.random(count)), rng.random(count)
    P = ((1 - r1)[:, None] * V[F[f, 0]] + (r1 * (1 - r2))[:, None] * V[F[f, 1]] + (r1 * r2)[:, None] * V[F[f, 2]])
    edge = np.mean(np.linalg.norm(V[F[:, 1]] - V[F[:, 0]], axis=1))
    n = fn[f] / np.linalg.norm(fn[f], axis=1, keepdims=True)
    return P + noise * edge * rng.standard_normal(count)[:, None] * n


def nearest_vertex(V, P):
    from scipy.spatial import cKDTree
    return cKDTree(V).query(P)[1]


def compare(program, mesh, degree, given_normals, neighbors, work, samples=0, noise=0., field=()):
    V, F = read_off(mesh)
    name = os.path.splitext(os.path.basename(mesh))[0]
    mesh_dirs = os.path.join(work, name + "_mesh.txt")
    mesh_mags = os.path.join(work, name + "_mesh.ply")
    m = run(program, [mesh, "--degree", str(degree), "--directions", mesh_dirs, "--ply", mesh_mags] + list(field))
    normals = vertex_normals(V, F)
    xyz = os.path.join(work, name + ".xyz")
    rows = np.hstack([V, normals]) if given_normals else V
    at = np.arange(len(V))
    if samples:
        rows = random_samples(V, F, samples, noise)
        at = nearest_vertex(V, rows)
    np.savetxt(xyz, rows, fmt="%.17g")
    cloud_dirs = os.path.join(work, name + "_cloud.txt")
    cloud_ply = os.path.join(work, name + "_cloud.ply")
    c = run(program, [xyz, "--degree", str(degree), "--neighbors", str(neighbors), "--directions", cloud_dirs,
                      "--ply", cloud_ply] + list(field))
    a, b = np.loadtxt(mesh_dirs)[at], np.loadtxt(cloud_dirs)
    with open(cloud_ply) as f:
        lines = f.read().split("end_header\n")[1].split("\n")
    cloud_normals = np.array([[float(x) for x in l.split()[3:6]] for l in lines if l.strip()])
    magnitude = magnitudes(mesh_mags, len(V))
    counted = (magnitude > 0.1 * magnitude.max())[at]
    share = share_within(a, b, cloud_normals, degree, 5., counted)
    what = f"{samples} samples, noise {noise}" if samples else f"{len(V)} points"
    print(f"{name}: {what}, {neighbors} neighbours; singular {c['singular_triangles']} (sum {c['index_sum']}, surface "
          f"{'closed, chi ' + str(c['surface_euler_characteristic']) if c['surface_is_closed'] else 'open'}) against the mesh's "
          f"{m['singular_faces']} (sum {m['index_sum']}); eigenvalue {c['eigenvalue'] or 0:.6g} against "
          f"{m['eigenvalue_bound'] or 0:.6g}; "
          f"{100 * share:.1f}% within 5 degrees ({np.count_nonzero(counted)} points counted); "
          f"compute {c['timings_ms']['total']:.0f} ms against {m['timings_ms']['total']:.0f} ms", flush=True)


def magnitudes(ply, count):
    with open(ply, "rb") as f:
        header = b""
        while not header.endswith(b"end_header\n"):
            header += f.readline()
        text = header.decode()
        names = [l.split()[-1] for l in text.splitlines() if l.startswith("property") and "list" not in l]
        if "binary" in text:
            return None
        rows = [f.readline().split() for _ in range(count)]
    return np.array([float(r[names.index("magnitude")]) for r in rows])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--program", required=True)
    parser.add_argument("--degree", type=int, default=4)
    parser.add_argument("--given-normals", action="store_true")
    parser.add_argument("--neighbors", type=int, default=12)
    parser.add_argument("--samples", type=int, default=0)
    parser.add_argument("--noise", type=float, default=0.)
    parser.add_argument("--field", default="", help="options for both runs, e.g. '--align curvature'")
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        for mesh in args.meshes:
            compare(args.program, mesh, args.degree, args.given_normals, args.neighbors, work, args.samples, args.noise,
                    args.field.split())
    return 0


if __name__ == "__main__":
    sys.exit(main())
