#!/usr/bin/python3
"""The smoothest field on faces against geometry-central's
computeSmoothestFaceDirectionField (with computeVertexIndex) and against the
package's own field on vertices, interleaved in one run: each round runs the
three once per mesh; the medians and their ratios are printed.

    compare_face_fields.py --gc-driver GC_FACE_DRIVER --program DIRECTION_FIELD [--before OLD_DIRECTION_FIELD]
                           [--reps 3] [--degree 4] MESHES
    compare_face_fields.py --prescription --program DIRECTION_FIELD [--reps 3] [--degree 4] MESHES

With --before: another build's field on faces too, in the same rounds (a change
measured before and after in one run).

With --prescription: the smoothest field on faces against prescribing its own
singular vertices (--prescribe), each a fresh run of the program.

GC_FACE_DRIVER is reference/gc_face_driver (built by reference/CMakeLists.txt
against the geometry-central tree of build_anchors.sh gc). The package's time
is the JSON's timings_ms.total: the library's computation, without reading
the file, as the driver times geometry-central.
"""
import argparse
import json
import os
import statistics
import subprocess


def gc_time(driver, mesh, degree):
    out = subprocess.run([driver, mesh, str(degree)], capture_output=True, text=True, check=True).stdout
    fields = dict(x.split("=", 1) for x in out.split() if "=" in x)
    return float(fields["time_ms"]), int(fields["nSingVertices"])


def package_time(program, mesh, degree, on):
    out = subprocess.run([program, mesh, "--degree", str(degree), "--on", on, "--json"], capture_output=True,
                         text=True, check=True, env=dict(os.environ, OPENBLAS_NUM_THREADS="1")).stdout
    data = json.loads(out)
    return data["timings_ms"]["total"], data.get("singular_vertices", data.get("singular_faces"))


def prescription_times(program, mesh, degree, work):
    """The smoothest field on faces, then its own singular vertices prescribed (one run each): both totals and
    whether the prescribed field has exactly those singular vertices."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    own, back = os.path.join(work, "own.txt"), os.path.join(work, "back.txt")
    run = [program, mesh, "--degree", str(degree), "--on", "faces", "--json"]
    smooth = json.loads(subprocess.run(run + ["--singularities", own], capture_output=True, text=True, check=True,
                                       env=env).stdout)
    placed = json.loads(subprocess.run(run + ["--prescribe", own, "--singularities", back], capture_output=True,
                                       text=True, check=True, env=env).stdout)
    with open(own) as a, open(back) as b:
        exact = a.read() == b.read()
    return smooth["timings_ms"]["total"], placed["timings_ms"]["total"], exact


def compare_prescription(a):
    import tempfile
    times = {m: {"smooth": [], "placed": []} for m in a.meshes}
    exact = {m: True for m in a.meshes}
    with tempfile.TemporaryDirectory() as work:
        for _ in range(a.reps):
            for m in a.meshes:
                smooth, placed, same = prescription_times(a.program, m, a.degree, work)
                times[m]["smooth"].append(smooth)
                times[m]["placed"].append(placed)
                exact[m] = exact[m] and same
    print("| mesh | smoothest on faces ms | its singular vertices prescribed ms | prescribed / smoothest | exact |")
    print("|---|---|---|---|---|")
    for m in a.meshes:
        smooth, placed = (statistics.median(times[m][k]) for k in ("smooth", "placed"))
        print("| %s | %.1f | %.1f | %.3f | %s |" % (os.path.basename(m), smooth, placed, placed / smooth,
                                                   "yes" if exact[m] else "NO"))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--gc-driver")
    parser.add_argument("--prescription", action="store_true",
                        help="instead: the smoothest field on faces against prescribing its own singular vertices")
    parser.add_argument("--program", required=True)
    parser.add_argument("--before", help="another build of the program: its field on faces in the same rounds")
    parser.add_argument("--reps", type=int, default=3)
    parser.add_argument("--degree", type=int, default=4)
    parser.add_argument("meshes", nargs="+")
    a = parser.parse_args()
    if a.prescription:
        return compare_prescription(a)
    if not a.gc_driver:
        parser.error("--gc-driver is required (or --prescription)")
    times = {m: {"gc": [], "faces": [], "vertices": [], "before": []} for m in a.meshes}
    singular = {}
    for _ in range(a.reps):
        for m in a.meshes:
            t, s_gc = gc_time(a.gc_driver, m, a.degree)
            times[m]["gc"].append(t)
            if a.before:
                times[m]["before"].append(package_time(a.before, m, a.degree, "faces")[0])
            t, s_faces = package_time(a.program, m, a.degree, "faces")
            times[m]["faces"].append(t)
            t, s_vertices = package_time(a.program, m, a.degree, "vertices")
            times[m]["vertices"].append(t)
            singular[m] = (s_gc, s_faces, s_vertices)
    before_head = " faces before ms | before / gc | before / vertices |" if a.before else ""
    print("| mesh | gc faces ms |" + before_head + " package faces ms | package vertices ms | faces / gc |"
          " faces / vertices | singular (gc, faces: vertices; vertices: faces) |")
    print("|---|---|" + ("---|---|---|" if a.before else "") + "---|---|---|---|---|")
    for m in a.meshes:
        gc, faces, vertices = (statistics.median(times[m][k]) for k in ("gc", "faces", "vertices"))
        before = ""
        if a.before:
            b = statistics.median(times[m]["before"])
            before = " %.1f | %.2f | %.2f |" % (b, b / gc, b / vertices)
        print("| %s | %.1f |%s %.1f | %.1f | %.2f | %.2f | %d, %d; %d |" %
              (os.path.basename(m), gc, before, faces, vertices, faces / gc, faces / vertices, *singular[m]))

if __name__ == "__main__":
    main()
