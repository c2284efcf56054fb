#!/usr/bin/env python3
"""The distributed path (the mesh on rank 0, the rows of A and M assembled by
each process from its faces, LOBPCG with multigrid in the gauge of the
processes' estimates) against the single-process eigen-solve, through
benchmark_distributed_field --compare: the same smallest eigenvalue (to 1e-8
relative) and the same singular faces, on a closed analytic mesh, a mesh with
boundary and a genus-2 mesh, on 1, 2 and 4 processes (4 on a small mesh:
ranges of about 80 vertices, most of whose faces belong to other processes).

    usage: test_distributed_field.py BENCHMARK_DISTRIBUTED_FIELD MPIEXEC SHARED_MESH_DIR OUTPUT_DIR
"""
import math
import os
import re
import shutil
import subprocess
import sys

from checks import MPI_ENVIRONMENT as ENV, Checks

BIN, MPIEXEC, SHARED, OUT = sys.argv[1:5]
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
check = Checks()

# an ellipsoid with axes 1, 0.8, 0.6 as a latitude-longitude mesh (poles fanned)
ellipsoid = os.path.join(OUT, "ellipsoid.off")
rings, sectors = 30, 48
points = [(0, 0, 0.6)]
for i in range(1, rings):
    t = math.pi * i / rings
    points += [(math.sin(t) * math.cos(2 * math.pi * j / sectors), 0.8 * math.sin(t) * math.sin(2 * math.pi * j / sectors),
                0.6 * math.cos(t)) for j in range(sectors)]
points.append((0, 0, -0.6))
ring = lambda i, j: 1 + (i - 1) * sectors + j % sectors
faces = [(0, ring(1, j), ring(1, j + 1)) for j in range(sectors)]
for i in range(1, rings - 1):
    for j in range(sectors):
        faces += [(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)), (ring(i, j), ring(i + 1, j + 1), ring(i, j + 1))]
faces += [(len(points) - 1, ring(rings - 1, j + 1), ring(rings - 1, j)) for j in range(sectors)]
with open(ellipsoid, "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(points), len(faces)) + "".join("%r %r %r\n" % p for p in points) +
            "".join("3 %d %d %d\n" % t for t in faces))

cases = [(ellipsoid, [1, 2, 4])]
for name, ranks in (("plane_holes.off", [1, 2]), ("eight.off", [2, 4])):
    path = os.path.join(SHARED, name)
    if os.path.exists(path):
        cases.append((path, ranks))
    else:
        check.skip("no shared mesh: " + name)

for mesh, ranks in cases:
    for k in ranks:
        tag = "%s on %d" % (os.path.basename(mesh), k)
        r = subprocess.run([MPIEXEC, "-np", str(k), BIN, mesh, "--compare"], capture_output=True, text=True, env=ENV,
                           timeout=600)
        check(r.returncode == 0, "%s: status %d %r" % (tag, r.returncode, r.stderr[-500:]))
        distributed = re.search(r"distributed: eigenvalue (\S+)\s+converged (\d)", r.stdout)
        single = re.search(r"relative difference (\S+)\s+singular faces not in both (\d+)", r.stdout)
        check(distributed is not None and distributed.group(2) == "1", "%s: converged: %r" % (tag, r.stdout[-400:]))
        check(single is not None and float(single.group(1)) <= 1e-8,
              "%s: eigenvalue as one process to 1e-8: %r" % (tag, single and single.group(1)))
        check(single is not None and single.group(2) == "0", "%s: the same singular faces: %r" % (tag, r.stdout[-400:]))
        check(re.search(r"cut edges (\d+)", r.stdout) is not None and
              (k == 1) == (re.search(r"cut edges (\d+)", r.stdout).group(1) == "0"),
              "%s: edges cut only between processes" % tag)

sys.exit(check.finish())
