#!/usr/bin/python3
"""The smoothest field on faces against geometry-central's
computeSmoothestFaceDirectionField (with computeVertexIndex) and against the
package's own field on vertices, interleaved in one run: each round runs the
three once per mesh; the medians and their ratios are printed.

    compare_face_fields.py --gc-driver GC_FACE_DRIVER --program DIRECTION_FIELD [--reps 3] [--degree 4] MESHES

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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--gc-driver", required=True)
    parser.add_argument("--program", required=True)
    parser.add_argument("--reps", type=int, default=3)
    parser.add_argument("--degree", type=int, default=4)
    parser.add_argument("meshes", nargs="+")
    a = parser.parse_args()
    times = {m: {"gc": [], "faces": [], "vertices": []} for m in a.meshes}
    singular = {}
    for _ in range(a.reps):
        for m in a.meshes:
            t, s_gc = gc_time(a.gc_driver, m, a.degree)
            times[m]["gc"].append(t)
            t, s_faces = package_time(a.program, m, a.degree, "faces")
            times[m]["faces"].append(t)
            t, s_vertices = package_time(a.program, m, a.degree, "vertices")
            times[m]["vertices"].append(t)
            singular[m] = (s_gc, s_faces, s_vertices)
    print("| mesh | gc faces ms | package faces ms | package vertices ms | faces / gc | faces / vertices |"
          " singular (gc, faces: vertices; vertices: faces) |")
    print("|---|---|---|---|---|---|---|")
    for m in a.meshes:
        gc, faces, vertices = (statistics.median(times[m][k]) for k in ("gc", "faces", "vertices"))
        print("| %s | %.1f | %.1f | %.1f | %.2f | %.2f | %d, %d; %d |" %
              (os.path.basename(m), gc, faces, vertices, faces / gc, faces / vertices, *singular[m]))


if __name__ == "__main__":
    main()
