#!/usr/bin/python3
"""The exchange files of direction_field read back by independent readers:
meshio (.vtu) and VTK's own Python module (.vtk, .vtu, .vtp), as ParaView and
the Python ecosystem read them. The singularities, normals and n must be found
where they should be.

    usage: test_exchange_readers.py DIRECTION_FIELD SHARED_MESH_DIR OUTPUT_DIR
Exit status 77 (skipped) when python3-meshio or python3-vtk9 is missing.
"""
import json
import math
import os
import shutil
import subprocess
import sys

from checks import Checks

try:
    import meshio
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError as e:
    print("SKIPPED: %s (Debian packages python3-meshio and python3-vtk9)" % e)
    sys.exit(77)

BIN, SHARED, OUT = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
check = Checks()


def run(args):
    r = subprocess.run([BIN] + args + ["--json"], capture_output=True, text=True,
                       env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
    check(r.returncode == 0, "run %s: %r" % (args, r.stderr))
    return json.loads(r.stdout) if r.returncode == 0 else None


# An octahedron with an unused vertex in front (it must not reach the VTK files).
mesh = os.path.join(OUT, "octahedron_isolated.off")
with open(mesh, "w") as f:
    f.write("OFF\n7 8 0\n5 5 5\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n")
    for t in [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]:
        f.write("3 %d %d %d\n" % tuple(v + 1 for v in t))
meshes = [(mesh, 6, 8)]
bunny = os.path.join(SHARED, "stanford_bunny_open.off")
if os.path.exists(bunny):
    meshes.append((bunny, None, None))

for path, used_vertices, faces in meshes:
    for n in [4, 3]:
        name = os.path.join(OUT, "%s_%d" % (os.path.basename(path), n))
        d = run([path, "--degree", str(n), "--vtk", name + ".vtu", "--singularity-list", name + ".sing",
                 "--streamlines", name + "_lines.vtp"])
        run([path, "--degree", str(n), "--vtk", name + ".vtk", "--streamlines", name + "_lines.vtu"])
        run([path, "--degree", str(n), "--streamlines", name + "_lines.obj"])
        run([path, "--degree", str(n), "--streamlines", name + "_lines.txt"])
        if d is None:
            continue
        used_vertices = used_vertices or d["mesh_vertices"] - d["isolated_vertices"]
        faces = faces or d["mesh_faces"]
        ns = d["singular_faces"]
        what = "%s n=%d" % (os.path.basename(path), n)

        # meshio: the .vtu
        m = meshio.read(name + ".vtu")
        blocks = {c.type: len(c.data) for c in m.cells}
        check(len(m.points) == used_vertices + ns, what + ": meshio points %d" % len(m.points))
        check(blocks.get("triangle") == faces and blocks.get("vertex", 0) == ns, what + ": meshio cells %s" % blocks)
        names = set(m.point_data)
        check({"singularity_index", "normals", "magnitude"} | {"direction_%d" % k for k in range(n)} <= names,
              what + ": meshio point data %s" % sorted(names))
        index = m.point_data["singularity_index"]
        check(abs(sum(index) * n - d["index_sum"]) < 1e-9 and sum(1 for x in index if x != 0) == ns,
              what + ": meshio singularity indices sum to index_sum / n")
        check(int(m.field_data["degree"][0]) == n, what + ": meshio field data degree")
        normals = m.point_data["normals"]
        d0 = m.point_data["direction_0"]
        check(all(abs(math.sqrt(sum(x * x for x in normals[i])) - 1) < 1e-9 and
                  abs(sum(a * b for a, b in zip(normals[i], d0[i]))) < 1e-9 for i in range(used_vertices)),
              what + ": unit normals orthogonal to the directions")

        # VTK: the legacy .vtk and the .vtu, with their active attributes
        for reader, ext in [(vtk.vtkPolyDataReader(), ".vtk"), (vtk.vtkXMLUnstructuredGridReader(), ".vtu")]:
            reader.SetFileName(name + ext)
            reader.Update()
            out = reader.GetOutput()
            pd = out.GetPointData()
            check(out.GetNumberOfPoints() == used_vertices + ns, what + ext + ": VTK points")
            check(pd.GetScalars() is not None and pd.GetScalars().GetName() == "singularity_index",
                  what + ext + ": singularity_index is the active scalars")
            check(pd.GetVectors() is not None and pd.GetVectors().GetName() == "direction_0",
                  what + ext + ": direction_0 is the active vectors")
            check(pd.GetNormals() is not None, what + ext + ": normals are the active normals")
            check(pd.GetArray("magnitude") is not None, what + ext + ": magnitude present, not active")
            fd = out.GetFieldData().GetArray("degree")
            check(fd is not None and int(fd.GetTuple1(0)) == n, what + ext + ": field data degree = n")
            values = vtk_to_numpy(pd.GetScalars())
            check(abs(values.sum() * n - d["index_sum"]) < 1e-9, what + ext + ": point indices sum")
            if ext == ".vtk":
                check(out.GetNumberOfVerts() == ns and out.GetNumberOfPolys() == faces, what + ext + ": verts, polys")

        # field lines: .vtp, .vtu, .obj against the text format
        lines = [l.split() for l in open(name + "_lines.txt") if l.strip()]
        points = sum(int(l[0]) for l in lines)
        r = vtk.vtkXMLPolyDataReader()
        r.SetFileName(name + "_lines.vtp")
        r.Update()
        check(r.GetOutput().GetNumberOfLines() == len(lines) and r.GetOutput().GetNumberOfPoints() == points,
              what + ": .vtp lines")
        r = vtk.vtkXMLUnstructuredGridReader()
        r.SetFileName(name + "_lines.vtu")
        r.Update()
        check(r.GetOutput().GetNumberOfCells() == len(lines) and r.GetOutput().GetNumberOfPoints() == points,
              what + ": .vtu lines")
        obj = [l.split() for l in open(name + "_lines.obj")]
        check(sum(1 for l in obj if l and l[0] == "l") == len(lines) and
              sum(1 for l in obj if l and l[0] == "v") == points, what + ": .obj lines")
        check(len(lines) > 0, what + ": some field lines")

# --mesh-out: a repaired file's mesh, read back, gives the same field
quads = os.path.join(OUT, "cube_quads.off")
with open(quads, "w") as f:
    f.write("OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
            "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n")
for ext in ["off", "obj", "ply"]:
    out_mesh = os.path.join(OUT, "repaired." + ext)
    a = run([quads, "--mesh-out", out_mesh, "--rosy", os.path.join(OUT, "a.rosy")])
    b = run([out_mesh, "--rosy", os.path.join(OUT, "b.rosy")])
    check(a is not None and b is not None and b["faces"] == a["mesh_faces"] and b["index_sum"] == a["index_sum"] and
          sum(b["repairs"].values()) == 0, "--mesh-out ." + ext + " is the repaired mesh")
    check(open(os.path.join(OUT, "a.rosy")).read() == open(os.path.join(OUT, "b.rosy")).read(),
          "--mesh-out ." + ext + ": the same per-face field")

check.finish()
