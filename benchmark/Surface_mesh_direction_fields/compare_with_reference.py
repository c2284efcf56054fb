#!/usr/bin/env python3
"""Runs the package and the paper's reference implementation (fieldgen) on the
same meshes, interleaved, and prints their times and peak memory as ratios.

    compare_with_reference.py [--anchors DIR] [--reps R] [--degree N] [--warm K] [--benchmark BIN]... MESH.off...

DIR holds the drivers built by ../shared/tools/reference_implementations/
build_anchors.sh (default: $ANCHORS, else "anchors" in the temporary directory,
where that script builds). Each repetition runs, one after the
other: fieldgen smoothest, the package smoothest, fieldgen curvature-aligned
(lambda_t = 0), the package curvature-aligned (the default lambda_t = 0); the
medians are compared. Times: fieldgen's time_ms (its own setup, assembly,
factorization, iterations and indices; file reading excluded) against the
package's total_ms (benchmark_direction_fields: mesh indexing to outputs; file
reading excluded). Memory: fieldgen's whole process (maximum resident set)
against the high-water mark of the package's computation, the mesh included.
Both use the same CHOLMOD and OpenBLAS, and the same environment. Each run
is a fresh process (cold: on virtual machines whose page faults are
expensive this weighs on both); --warm K repeats the computation K times in
each process instead (fieldgen's median, the package's best of K).

--benchmark BIN, given more than once (say the build of an earlier commit and
the current one), runs each of them after fieldgen in every repetition: a
change is measured before and after against the reference in one run, one
row per binary (the column `package` names it). BIN may carry options in
one argument: --benchmark "build/bin/benchmark_direction_fields
--openblas-thread-control off".
"""
import argparse
import csv
import io
import os
import re
import shlex
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def run_fieldgen(anchors, obj, degree, mode, warm):
    out = subprocess.run(["/usr/bin/time", "-f", "MAXRSS %M", os.path.join(anchors, "fg_driver", "fg_driver_patched"),
                          obj, str(degree), f"--mode={mode}", f"--reps={warm}"], capture_output=True, text=True, check=True)
    text = out.stdout + out.stderr
    time_ms = float(re.search(r"RESULT .* time_ms=([0-9.]+)", text).group(1))
    peak_mb = float(re.search(r"MAXRSS ([0-9]+)", text).group(1)) / 1024.
    singular = int(re.search(r"nSingFaces=([0-9]+)", text).group(1))
    return time_ms, peak_mb, singular


def run_package(benchmark, mesh, degree, aligned, warm):
    args = shlex.split(benchmark) + ["--degree", str(degree), "--repeat", str(warm), mesh]
    if aligned:
        args[-1:-1] = ["--align", "curvature"]
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    rows = list(csv.DictReader(io.StringIO(out[out.index("mesh,vertices"):])))
    row = rows[0]
    return float(row["total_ms"]), float(row["peak_memory_mb"]), int(row["singular_faces"])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--anchors", default=os.environ.get("ANCHORS", os.path.join(tempfile.gettempdir(), "anchors")))
    parser.add_argument("--benchmark", action="append")
    parser.add_argument("--reps", type=int, default=3)
    parser.add_argument("--degree", type=int, default=4)
    parser.add_argument("--warm", type=int, default=1)
    parser.add_argument("meshes", nargs="+")
    a = parser.parse_args()
    a.benchmark = a.benchmark or [os.path.join(HERE, "..", "..", "build", "bin", "benchmark_direction_fields")]
    for tool in [os.path.join(a.anchors, "fg_driver", "fg_driver_patched"), os.path.join(a.anchors, "off2obj")] + \
            [shlex.split(b)[0] for b in a.benchmark]:
        if not os.access(tool, os.X_OK):
            sys.exit(f"compare_with_reference.py: {tool} is missing (see the docstring)")
    print("mesh,field,package,reference_ms,package_ms,time_ratio,reference_peak_mb,package_peak_mb,memory_ratio,"
          "reference_singular_faces,package_singular_faces")
    with tempfile.TemporaryDirectory() as tmp:
        for mesh in a.meshes:
            obj = os.path.join(tmp, os.path.basename(mesh) + ".obj")
            subprocess.run([os.path.join(a.anchors, "off2obj"), mesh, obj], check=True, capture_output=True)
            results = {(field, who): [] for field in ("smoothest", "aligned") for who in ["reference"] + a.benchmark}
            for _ in range(a.reps):
                for field, mode in (("smoothest", "smooth"), ("aligned", "aligned")):
                    results[(field, "reference")].append(run_fieldgen(a.anchors, obj, a.degree, mode, a.warm))
                    for binary in a.benchmark:
                        results[(field, binary)].append(run_package(binary, mesh, a.degree, field == "aligned", a.warm))
            for field in ("smoothest", "aligned"):
                ref = results[(field, "reference")]
                rt, rm = statistics.median(r[0] for r in ref), statistics.median(r[1] for r in ref)
                for binary in a.benchmark:
                    pkg = results[(field, binary)]
                    pt, pm = statistics.median(p[0] for p in pkg), statistics.median(p[1] for p in pkg)
                    print(f"{os.path.basename(mesh)},{field},{binary},{rt:.1f},{pt:.1f},{pt / rt:.3f},{rm:.1f},{pm:.1f},"
                          f"{pm / rm:.3f},{ref[0][2]},{pkg[0][2]}", flush=True)
                    print(f"  {field} {binary}: times reference {[round(r[0]) for r in ref]} package "
                          f"{[round(p[0]) for p in pkg]}", file=sys.stderr)


if __name__ == "__main__":
    main()
