#!/usr/bin/env python3
"""How much of a whole direction_field run is file work (reading, repair,
writing) rather than the computation.

    io_share.py [--reps R] [--old PATH] [--outputs "ARGS"] [--subdivide] MESH...

Runs build/bin/direction_field MESH --json (plus the outputs, by default
--directions) R times per mesh, interleaved with the program at --old if
given (an earlier build, for a before/after ratio in the same session), and
prints per program the median wall time of the whole process, the library's
computation (timings_ms.total), everything else (wall - computation: process
start, reading, repair, writing) and its share of the wall time, and the
program's own io_ms (its reading, repair and writing, when it reports them).
--subdivide also runs each mesh split once into four (midpoint subdivision,
written to a temporary OFF): 4 times the faces.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
default_bin = os.path.join(here, "..", "..", "build", "bin", "direction_field")


def subdivided(path, folder):
    """The OFF mesh at `path`, each triangle split into four at its edge midpoints."""
    words = [l.split("#")[0] for l in open(path)]
    tokens = " ".join(words).split()
    assert tokens[0].endswith("OFF")
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    points = [tuple(float(x) for x in tokens[at + 3 * i:at + 3 * i + 3]) for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(tokens[at])
        faces.append(tuple(int(x) for x in tokens[at + 1:at + 1 + k]))
        at += 1 + k
    middle = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in middle:
            middle[key] = len(points)
            points.append(tuple((x + y) / 2 for x, y in zip(points[a], points[b])))
        return middle[key]

    out_faces = []
    for a, b, c in faces:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out_faces += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    out = os.path.join(folder, os.path.basename(path).replace(".off", "_split4.off"))
    with open(out, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(out_faces)))
        f.write("".join("%.17g %.17g %.17g\n" % p for p in points))
        f.write("".join("3 %d %d %d\n" % t for t in out_faces))
    return out


def run(program, mesh, outputs, folder):
    args = [program, mesh, "--json"] + [a.replace("OUT", folder) for a in outputs.split()]
    start = time.perf_counter()
    r = subprocess.run(args, capture_output=True, text=True, env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
    wall = 1000 * (time.perf_counter() - start)
    if r.returncode != 0:
        sys.exit("%s failed: %s" % (" ".join(args), r.stderr))
    d = json.loads(r.stdout)
    return wall, d["timings_ms"]["total"], d.get("io_ms")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("meshes", nargs="+")
    p.add_argument("--reps", type=int, default=3)
    p.add_argument("--bin", default=default_bin)
    p.add_argument("--old")
    p.add_argument("--outputs", default="--directions OUT/directions.txt")
    p.add_argument("--subdivide", action="store_true")
    a = p.parse_args()
    folder = tempfile.mkdtemp(prefix="smdf_io_")
    meshes = list(a.meshes) + ([subdivided(m, folder) for m in a.meshes] if a.subdivide else [])
    programs = [("new", a.bin)] + ([("old", a.old)] if a.old else [])
    print("%-28s %-4s %9s %9s %9s %6s %8s" % ("mesh", "prog", "wall ms", "compute", "rest", "rest%", "io_ms"))
    for mesh in meshes:
        samples = {name: [] for name, _ in programs}
        for _ in range(a.reps):
            for name, program in programs:
                samples[name].append(run(program, mesh, a.outputs, folder))
        for name, _ in programs:
            wall = statistics.median(s[0] for s in samples[name])
            compute = statistics.median(s[1] for s in samples[name])
            io = [s[2] for s in samples[name] if s[2] is not None]
            print("%-28s %-4s %9.0f %9.0f %9.0f %5.0f%% %8s" % (
                os.path.basename(mesh)[:28], name, wall, compute, wall - compute, 100 * (wall - compute) / wall,
                "%.0f" % statistics.median(io) if io else "-"))


if __name__ == "__main__":
    main()
