#!/usr/bin/env python3
"""The Python module's overhead: the wall time of one call of
compute_globally_optimal_directions() from Python (array checks, the mesh
built from V and F, result arrays) against the C++ computation's own total
(Result.timings["total_ms"]), on one mesh, REPS calls interleaved.

    usage: PYTHONPATH=build/python python3 python_overhead.py MESH [REPS]
"""
import statistics
import sys
import time

import surface_mesh_direction_fields as smdf

V, F = smdf.read_mesh(sys.argv[1])
reps = int(sys.argv[2]) if len(sys.argv) > 2 else 5
walls, totals = [], []
for _ in range(reps):
    start = time.perf_counter()
    r = smdf.compute_globally_optimal_directions(V, F, degree=4)
    walls.append(1000 * (time.perf_counter() - start))
    totals.append(r.timings["total_ms"])
wall, total = statistics.median(walls), statistics.median(totals)
print("%s: %d vertices, %d faces" % (sys.argv[1], len(V), len(F)))
print("call from Python %.1f ms, C++ total %.1f ms, overhead %.1f ms = %.1f%% (medians of %d)" %
      (wall, total, wall - total, 100 * (wall - total) / total, reps))
