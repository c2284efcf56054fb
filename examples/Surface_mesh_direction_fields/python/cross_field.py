#!/usr/bin/env python3
"""A cross field with the installed package (pip install --no-build-isolation .):
a mesh file read and repaired as the program does, the field computed, written
as a .vtu that ParaView opens, and its singularities listed. Typed: mypy
--strict checks it against the package's stubs.

    usage: cross_field.py MESH OUTPUT.vtu [DEGREE]
"""
import sys
from pathlib import Path

import numpy as np

import surface_mesh_direction_fields as smdf


def main(mesh: Path, output: Path, degree: int) -> None:
    V, F = mesh_arrays = smdf.read_mesh(mesh)
    repairs = mesh_arrays.repairs
    result = smdf.compute_globally_optimal_directions(V, F, degree=degree)
    smdf.write_vtk(output, V, F, result)
    indices = result.singular_faces[:, 1]
    print(f"{len(F)} faces ({sum(repairs.values())} repairs), {len(indices)} singular faces: "
          f"{int(np.sum(indices > 0))} positive, {int(np.sum(indices < 0))} negative, index sum {result.index_sum}/{degree}")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(Path(sys.argv[1]), Path(sys.argv[2]), int(sys.argv[3]) if len(sys.argv) > 3 else 4)
