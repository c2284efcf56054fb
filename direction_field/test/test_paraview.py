#!/usr/bin/env python3
"""The files of --vtk and --vtk-singularities as ParaView shows them, through
pvbatch (ParaView's Python, Debian's paraview and python3-paraview; the latter
conflicts with python3-vtk9, so this test is optional: exit status 77 when
ParaView's Python is not there). Checked with ParaView's default settings: a
Glyph filter on the field draws arrows of non-zero size, the markers are
coloured by their index; then show_in_paraview.py shows all n directions and
writes its picture.

    usage: test_paraview.py DIRECTION_FIELD SHOW_IN_PARAVIEW_PY OUTPUT_DIR
Set SMDF_PARAVIEW_PYTHONPATH to where paraview.simple lives if it is not on
ParaView's own path.
"""
import os
import shutil
import subprocess
import sys

from checks import Checks, refined_octahedron

BIN, SCRIPT, OUT = sys.argv[1], sys.argv[2], sys.argv[3]
pvbatch = shutil.which("pvbatch")
if pvbatch is None:
    print("SKIPPED: no pvbatch (Debian packages paraview and python3-paraview)")
    sys.exit(77)
env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
if os.environ.get("SMDF_PARAVIEW_PYTHONPATH"):
    env["PYTHONPATH"] = os.environ["SMDF_PARAVIEW_PYTHONPATH"] + os.pathsep + env.get("PYTHONPATH", "")
command = [pvbatch]
if not os.environ.get("DISPLAY"):
    if shutil.which("xvfb-run") is None:
        print("SKIPPED: no display and no xvfb-run")
        sys.exit(77)
    command = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", pvbatch]
probe = subprocess.run(command + ["-c", "import paraview.simple"], capture_output=True, text=True, env=env, timeout=120)
if probe.returncode != 0:
    print("SKIPPED: pvbatch cannot import paraview.simple (python3-paraview)")
    sys.exit(77)
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
check = Checks()

CHECK = r'''
import sys
sys.path.insert(0, sys.argv[1])
from paraview import simple
import show_in_paraview
field, markers, n, picture = sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
mesh = simple.OpenDataFile(field)
surface = simple.Show(mesh)
glyph = simple.Glyph(Input=mesh)                # every setting ParaView's default
glyph.UpdatePipeline()
info = glyph.GetDataInformation()
b = info.GetBounds()
print("default_glyph_points", info.GetNumberOfPoints())
print("default_glyph_extent", max(b[1] - b[0], b[3] - b[2], b[5] - b[4]))
print("default_glyph_scale_array", glyph.ScaleArray[1])
print("default_glyph_orientation", glyph.OrientationArray[1])
print("surface_coloring", surface.ColorArrayName[1] or "none")
m = simple.OpenDataFile(markers)
print("marker_coloring", simple.Show(m).ColorArrayName[1])
for s in list(simple.GetSources().values()):
    simple.Delete(s)
glyphs = show_in_paraview.show_direction_field(field, markers)
print("script_glyph_filters", len(glyphs))
print("script_glyph_points", min(g.GetDataInformation().GetNumberOfPoints() for g in glyphs))
simple.SaveScreenshot(picture, simple.GetActiveView(), ImageResolution=[800, 600])
'''
check_script = os.path.join(OUT, "check.py")
with open(check_script, "w") as f:
    f.write(CHECK)

octahedron = os.path.join(OUT, "sphere.off")
# a subdivided octahedron on the unit sphere: 8 singularities of index +1/4 for n = 4
points, faces = refined_octahedron(3)
with open(octahedron, "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(points), len(faces)) + "".join("%r %r %r\n" % p for p in points) +
            "".join("3 %d %d %d\n" % t for t in faces))

for n, ext, on in [(4, "vtu", "vertices"), (1, "vtk", "vertices"), (3, "vtu", "vertices"), (4, "vtu", "faces"),
                   (1, "vtk", "faces")]:
    field, markers = [os.path.join(OUT, "%s_%d_%s.%s" % (kind, n, on, ext)) for kind in ("field", "singularities")]
    r = subprocess.run([BIN, octahedron, "--degree", str(n), "--on", on, "--vtk", field, "--vtk-singularities",
                        markers, "--quiet"], capture_output=True, text=True, env=env)
    check(r.returncode == 0, "direction_field n=%d: %r" % (n, r.stderr))
    picture = os.path.join(OUT, "paraview_%d_%s.png" % (n, on))
    r = subprocess.run(command + [check_script, os.path.dirname(os.path.abspath(SCRIPT)), field, markers, str(n),
                                  picture], capture_output=True, text=True, env=env, timeout=300)
    values = dict(l.split(None, 1) for l in r.stdout.splitlines() if l.count(" ") >= 1 and l.split()[0].islower()
                  and "_" in l.split()[0])
    what = "n=%d .%s on %s" % (n, ext, on)
    check(r.returncode == 0, what + ": pvbatch ran (%r)" % r.stderr[-400:])
    if r.returncode != 0:
        continue
    check(int(values["default_glyph_points"]) > 0 and float(values["default_glyph_extent"]) > 0.1,
          what + ": ParaView's default Glyph draws arrows (%s points, extent %s)" %
          (values["default_glyph_points"], values["default_glyph_extent"]))
    check(values["default_glyph_scale_array"] == "No scale array" and values["default_glyph_orientation"] ==
          "direction_0", what + ": default Glyph: no scale array, oriented by direction_0")
    check(values["surface_coloring"] == "none", what + ": the mesh is not coloured by an array")
    check(values["marker_coloring"] == "singularity_index", what + ": the markers are coloured by their index")
    check(int(values["script_glyph_filters"]) == (n if n % 2 else n // 2) and int(values["script_glyph_points"]) > 0,
          what + ": show_in_paraview.py shows every direction")
    check(os.path.getsize(picture) > 10000, what + ": show_in_paraview.py's picture written")
check.finish()
