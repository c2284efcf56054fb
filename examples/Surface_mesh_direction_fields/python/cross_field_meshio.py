#!/usr/bin/env python3
"""A cross field with the Python module: a mesh read by meshio, the field
written as a .vtu that ParaView opens (the directions as point data, the
singular triangles' index as cell data).

    usage: cross_field_meshio.py MESH OUTPUT.vtu [DEGREE]
"""
import sys

import meshio
import numpy as np

import surface_mesh_direction_fields as smdf

if len(sys.argv) < 3:
    sys.exit(__doc__)
mesh = meshio.read(sys.argv[1])
V = np.asarray(mesh.points, dtype=np.float64)
F = mesh.get_cells_type("triangle").astype(np.int64)
degree = int(sys.argv[3]) if len(sys.argv) > 3 else 4
r = smdf.compute_globally_optimal_directions(V, F, degree=degree)
index = np.zeros(len(F))
index[r.singular_faces[:, 0]] = r.singular_faces[:, 1] / degree
meshio.write(sys.argv[2], meshio.Mesh(V, [("triangle", F)], point_data={"direction_0": r.directions},
                                      cell_data={"singularity_index": [index]}))
print("%d singular faces, index sum %d/%d, %.1f ms" % (len(r.singular_faces), r.index_sum, degree,
                                                      r.timings["total_ms"]))
