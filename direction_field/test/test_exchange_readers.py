#!/usr/bin/python3
"""The exchange files of direction_field read back by independent readers,
each with its default settings: meshio (.vtk, .vtu) and VTK's own Python
module (.vtk, .vtu, .vtp), as ParaView and the Python ecosystem read them. The
singularities, normals, all n directions and n must be found where they
should be, with their names and shapes.

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
    import numpy
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

def vtk_read(path):
    """VTK's reader for the file's kind, with its default settings."""
    reader = {".vtk": vtk.vtkUnstructuredGridReader, ".vtu": vtk.vtkXMLUnstructuredGridReader,
              ".vtp": vtk.vtkXMLPolyDataReader}[os.path.splitext(path)[1]]()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def check_field_meshio(m, what, n, used_vertices, faces, ns, index_sum):
    blocks = {c.type: len(c.data) for c in m.cells}
    check(len(m.points) == used_vertices and blocks == {"triangle": faces}, what + ": points %d, cells %s" %
          (len(m.points), blocks))
    shapes = {k: v.shape for k, v in m.point_data.items()}
    expected = dict({"normals": (used_vertices, 3), "magnitude": (used_vertices,), "directions": (used_vertices, 3 * n)},
                    **{"direction_%d" % k: (used_vertices, 3) for k in range(n)})
    check(all(shapes.get(k) == v for k, v in expected.items()), what + ": point arrays %s" % shapes)
    if not all(shapes.get(k) == v for k, v in expected.items()):
        return
    index = m.cell_data["singularity_index"][0].reshape(-1)
    check(abs(index.sum() * n - index_sum) < 1e-9 and (index != 0).sum() == ns,
          what + ": the triangles' singularity_index sums to index_sum / n")
    d = m.point_data["directions"]
    check(all(numpy.array_equal(d[:, 3 * k:3 * k + 3], m.point_data["direction_%d" % k]) for k in range(n)),
          what + ": directions holds direction_0 ... direction_{n-1}")
    check(numpy.abs(numpy.linalg.norm(d.reshape(-1, 3), axis=1) - 1).max() < 1e-9, what + ": every direction unit")
    normals, d0 = m.point_data["normals"], m.point_data["direction_0"]
    check(numpy.abs(numpy.linalg.norm(normals, axis=1) - 1).max() < 1e-9 and
          numpy.abs((normals * d0).sum(axis=1)).max() < 1e-9, what + ": unit normals orthogonal to the directions")


def check_field_vtk(out, what, n, used_vertices, faces, index_sum, xml):
    pd, cd = out.GetPointData(), out.GetCellData()
    check(out.GetNumberOfPoints() == used_vertices and out.GetNumberOfCells() == faces, what + ": VTK points, cells")
    check(pd.GetScalars() is None and cd.GetScalars() is None, what + ": no active scalars (ParaView's Glyph would "
          "take them as its scale array)")
    check(pd.GetVectors() is not None and pd.GetVectors().GetName() == "direction_0", what + ": direction_0 active")
    check(not xml or (pd.GetNormals() is not None and pd.GetNormals().GetName() == "normals"), what + ": normals")
    arrays = {pd.GetArrayName(i): pd.GetArray(i).GetNumberOfComponents() for i in range(pd.GetNumberOfArrays())}
    expected = dict({"normals": 3, "magnitude": 1, "directions": 3 * n}, **{"direction_%d" % k: 3 for k in range(n)})
    check(arrays == expected, what + ": VTK point arrays by default %s" % arrays)
    check(cd.GetArray("singularity_index") is not None and
          abs(vtk_to_numpy(cd.GetArray("singularity_index")).sum() * n - index_sum) < 1e-9,
          what + ": cell data singularity_index")
    fd = out.GetFieldData().GetArray("degree")
    check(fd is not None and int(fd.GetTuple1(0)) == n, what + ": field data degree = n")


for path, used_vertices, faces in meshes:
    for n in [4, 3, 1]:
        name = os.path.join(OUT, "%s_%d" % (os.path.basename(path), n))
        d = run([path, "--degree", str(n), "--vtk", name + ".vtu", "--singularity-list", name + ".sing",
                 "--vtk-singularities", name + "_sing.vtu", "--streamlines", name + "_lines.vtp"])
        run([path, "--degree", str(n), "--vtk", name + ".vtk", "--vtk-singularities", name + "_sing.vtk",
             "--streamlines", name + "_lines.vtu"])
        run([path, "--degree", str(n), "--streamlines", name + "_lines.vtk"])
        run([path, "--degree", str(n), "--streamlines", name + "_lines.obj"])
        run([path, "--degree", str(n), "--streamlines", name + "_lines.txt"])
        if d is None:
            continue
        used_vertices = used_vertices or d["mesh_vertices"] - d["isolated_vertices"]
        faces = faces or d["mesh_faces"]
        ns = d["singular_faces"]
        what = "%s n=%d" % (os.path.basename(path), n)
        for ext in [".vtu", ".vtk"]:
            check_field_meshio(meshio.read(name + ext), what + " meshio " + ext, n, used_vertices, faces, ns,
                               d["index_sum"])
            check_field_vtk(vtk_read(name + ext), what + " VTK " + ext, n, used_vertices, faces, d["index_sum"],
                            ext == ".vtu")
            # the singularity markers: an octahedron per singular face, coloured by its index
            m = meshio.read(name + "_sing" + ext)
            index = m.point_data.get("singularity_index", numpy.zeros(1)).reshape(-1)
            check(len(m.points) == 6 * ns and {c.type: len(c.data) for c in m.cells} == ({"triangle": 8 * ns} if ns else {})
                  and abs(index.sum() * n - 6 * d["index_sum"]) < 1e-9, what + ext + ": meshio reads the markers")
            out = vtk_read(name + "_sing" + ext)
            check(out.GetNumberOfCells() == 8 * ns and (ns == 0 or out.GetPointData().GetScalars().GetName() ==
                  "singularity_index"), what + ext + ": VTK reads the markers, their index the active scalars")

        # field lines: .vtp, .vtu, .vtk, .obj against the text format
        lines = [l.split() for l in open(name + "_lines.txt") if l.strip()]
        points = sum(int(l[0]) for l in lines)
        out = vtk_read(name + "_lines.vtp")
        check(out.GetNumberOfLines() == len(lines) and out.GetNumberOfPoints() == points, what + ": .vtp lines")
        for ext in [".vtu", ".vtk"]:
            out = vtk_read(name + "_lines" + ext)
            check(out.GetNumberOfCells() == points - len(lines) and out.GetNumberOfPoints() == points,
                  what + ": VTK reads the " + ext + " line segments")
            m = meshio.read(name + "_lines" + ext)
            ids = m.cell_data["line"][0].reshape(-1) if "line" in m.cell_data else numpy.zeros(0)
            check([c.type for c in m.cells] == ["line"] and len(m.cells[0].data) == points - len(lines) and
                  len(set(ids.tolist())) == len(lines), what + ": meshio keeps the " + ext + " field lines")
        obj = [l.split() for l in open(name + "_lines.obj")]
        check(sum(1 for l in obj if l and l[0] == "l") == len(lines) and
              sum(1 for l in obj if l and l[0] == "v") == points, what + ": .obj lines")
        check(len(lines) > 0, what + ": some field lines")



def check_face_field(m, out, what, n, used_vertices, faces, d):
    """A field on faces (--on faces): per-cell directions and normals, direction_0 the active cell vectors (so
    that ParaView's Glyph filter puts its arrows at the triangles' centres), the singular vertices' index k / n
    as point data, no active scalars."""
    cells = {c.type: len(c.data) for c in m.cells}
    shapes = {k: v[0].shape for k, v in m.cell_data.items()}
    expected = dict({"normals": (faces, 3), "directions": (faces, 3 * n)},
                    **{"direction_%d" % k: (faces, 3) for k in range(n)})
    check(len(m.points) == used_vertices and cells == {"triangle": faces} and
          all(shapes.get(k) == v for k, v in expected.items()), what + ": meshio cell arrays %s" % shapes)
    index = m.point_data.get("singularity_index", numpy.zeros(0)).reshape(-1)
    check(len(index) == used_vertices and abs(index.sum() * n - d["index_sum"]) < 1e-9 and
          (index != 0).sum() == d["singular_vertices"], what + ": meshio point data singularity_index")
    if all(shapes.get(k) == v for k, v in expected.items()):
        all_d = m.cell_data["directions"][0]
        normals = m.cell_data["normals"][0]
        check(numpy.abs(numpy.linalg.norm(all_d.reshape(-1, 3), axis=1) - 1).max() < 1e-9 and
              numpy.abs((normals * m.cell_data["direction_0"][0]).sum(axis=1)).max() < 1e-9,
              what + ": unit directions in the faces' planes")
    pd, cd = out.GetPointData(), out.GetCellData()
    check(pd.GetScalars() is None and cd.GetScalars() is None and pd.GetVectors() is None and
          cd.GetVectors() is not None and cd.GetVectors().GetName() == "direction_0",
          what + ": VTK: direction_0 the active cell vectors, no active scalars")
    check(out.GetNumberOfPoints() == used_vertices and out.GetNumberOfCells() == faces and
          int(out.GetFieldData().GetArray("degree").GetTuple1(0)) == n, what + ": VTK points, cells, degree")


for path, used_vertices, faces in meshes:
    for n in [4, 1]:
        name = os.path.join(OUT, "%s_faces_%d" % (os.path.basename(path), n))
        d = run([path, "--on", "faces", "--degree", str(n), "--vtk", name + ".vtu", "--vtk-singularities",
                 name + "_sing.vtu", "--streamlines", name + "_lines.vtp"])
        run([path, "--on", "faces", "--degree", str(n), "--vtk", name + ".vtk", "--vtk-singularities",
             name + "_sing.vtk"])
        if d is None:
            continue
        what = "%s on faces n=%d" % (os.path.basename(path), n)
        used = used_vertices or d["mesh_vertices"]
        nf = faces or d["mesh_faces"]
        ns = d["singular_vertices"]
        for ext in [".vtu", ".vtk"]:
            check_face_field(meshio.read(name + ext), vtk_read(name + ext), what + " " + ext, n, used, nf, d)
            if ns == 0 and ext == ".vtu":
                continue
            m = meshio.read(name + "_sing" + ext)
            index = m.point_data.get("singularity_index", numpy.zeros(1)).reshape(-1)
            check(len(m.points) == 6 * ns and abs(index.sum() * n - 6 * d["index_sum"]) < 1e-9,
                  what + ext + ": meshio reads a marker per singular vertex")
        out = vtk_read(name + "_lines.vtp")
        if faces is None:  # (every face of the octahedron has a singular vertex: no line can start)
            check(out.GetNumberOfLines() > 0, what + ": field lines of the field on faces (.vtp)")

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

# A field without singularities (a flat square): the markers in legacy .vtk
# are a dataset without points that meshio and VTK read; a .vtu without
# points meshio cannot read, so it is left out, an older file of that name
# removed, and the JSON says so.
square = os.path.join(OUT, "square.off")
with open(square, "w") as f:
    f.write("OFF\n16 18 0\n" + "".join("%d %d 0\n" % (i, j) for j in range(4) for i in range(4)))
    for j in range(3):
        for i in range(3):
            a = 4 * j + i
            f.write("3 %d %d %d\n3 %d %d %d\n" % (a, a + 1, a + 5, a, a + 5, a + 4))
stale = os.path.join(OUT, "square_sing.vtu")
open(stale, "w").write("an older file")
d = run([square, "--vtk-singularities", stale])
check(d is not None and d["singular_faces"] == 0 and d["outputs_left_out"] == ["--vtk-singularities"] and
      not os.path.exists(stale), "no singularity: the .vtu markers are left out, the older file removed, the JSON says so")
d = run([square, "--vtk-singularities", os.path.join(OUT, "square_sing.vtk")])
m = meshio.read(os.path.join(OUT, "square_sing.vtk"))
check(d is not None and d["outputs_left_out"] == [] and len(m.points) == 0 and
      vtk_read(os.path.join(OUT, "square_sing.vtk")).GetNumberOfPoints() == 0,
      "no singularity: meshio and VTK read the .vtk markers without points")

check.finish()
