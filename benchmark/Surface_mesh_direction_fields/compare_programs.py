#!/usr/bin/env python3
"""Compares builds of the direction_field program (what users run), and
optionally the paper's reference code (fieldgen), on the same meshes in one
run, the order of the programs alternated from one repetition to the next
(on the shared 2-core machines the process that runs right after another is
slower, so a fixed order favours one side).

    compare_programs.py --program LABEL=PATH [--program LABEL=PATH ...] [--anchors DIR]
                        [--reps R] [--cases smoothest,aligned,faces,prescribed] MESH.off...

Each case runs one fresh process per program and repetition:
  smoothest   direction_field MESH --json
  aligned     direction_field MESH --align curvature --json
  faces       direction_field MESH --on faces --json
  prescribed  direction_field MESH --prescribe EDIT --json, EDIT the smoothest field's singular faces with
              the first one moved to a neighbouring face's place (an edit, as a user makes one)
Time: the JSON's timings_ms.total (the library's computation; file reading
and writing excluded). Memory: the process's maximum resident set
(/usr/bin/time). With --anchors (the drivers of
../shared/tools/reference_implementations/build_anchors.sh), fieldgen runs
the smoothest and the aligned case in the same rotation, and each program's
median time and memory are given as ratios to fieldgen's.
The table: per mesh and case, each program's time range and median, memory,
and the ratio of the median to the first program's (and to fieldgen's).
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import tempfile


def maximum_resident_mb(stderr):
    found = re.search(r"MAXRSS ([0-9]+)", stderr)
    return float(found.group(1)) / 1024. if found else float("nan")


def run_program(path, mesh, case, edit):
    args = [path, mesh, "--json", "--quiet"]
    if case == "aligned":
        args += ["--align", "curvature"]
    elif case == "faces":
        args += ["--on", "faces"]
    elif case == "prescribed":
        args += ["--prescribe", edit]
    out = subprocess.run(["/usr/bin/time", "-f", "MAXRSS %M"] + args, capture_output=True, text=True, check=True)
    d = json.loads(out.stdout)
    singular = d.get("singular_faces", d.get("singular_vertices"))
    return d["timings_ms"]["total"], maximum_resident_mb(out.stderr), singular


def run_fieldgen(anchors, obj, case):
    mode = "smooth" if case == "smoothest" else "aligned"
    out = subprocess.run(["/usr/bin/time", "-f", "MAXRSS %M", os.path.join(anchors, "fg_driver", "fg_driver_patched"),
                          obj, "4", f"--mode={mode}"], capture_output=True, text=True, check=True)
    text = out.stdout + out.stderr
    return (float(re.search(r"RESULT .* time_ms=([0-9.]+)", text).group(1)), maximum_resident_mb(text),
            int(re.search(r"nSingFaces=([0-9]+)", text).group(1)))


def prescription_edit(program, mesh, folder):
    """The smoothest field's singular faces, the first moved to another face of the file (face + 1)."""
    own = os.path.join(folder, "own.txt")
    subprocess.run([program, mesh, "--singularities", own, "--quiet"], check=True, capture_output=True)
    lines = [l for l in open(own).read().splitlines() if l and not l.startswith("#")]
    faces = {int(l.split()[0]) for l in lines}
    first, k = map(int, lines[0].split())
    moved = next(f for f in range(first + 1, first + 1000) if f not in faces)
    edit = os.path.join(folder, "edit.txt")
    with open(edit, "w") as f:
        f.write("%d %d\n" % (moved, k) + "".join(l + "\n" for l in lines[1:]))
    return edit


def summary(values):
    return "%.0f-%.0f (%.0f)" % (min(values), max(values), statistics.median(values))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--program", action="append", required=True, help="LABEL=PATH of a direction_field build")
    parser.add_argument("--anchors", default="", help="the reference drivers (fieldgen) to compare with")
    parser.add_argument("--reps", type=int, default=3)
    parser.add_argument("--cases", default="smoothest,aligned,faces,prescribed")
    parser.add_argument("meshes", nargs="+")
    a = parser.parse_args()
    programs = [p.split("=", 1) for p in a.program]
    cases = a.cases.split(",")
    folder = tempfile.mkdtemp(prefix="compare_programs_")
    print("mesh | case | program | time ms: range (median) | ratio to %s | to fieldgen | peak MB | to fieldgen | "
          "singular" % programs[0][0])
    for mesh in a.meshes:
        obj = None
        if a.anchors:
            obj = os.path.join(folder, os.path.basename(mesh) + ".obj")
            subprocess.run([os.path.join(a.anchors, "off2obj"), mesh, obj], check=True, capture_output=True)
        edit = prescription_edit(programs[0][1], mesh, folder) if "prescribed" in cases else None
        for case in cases:
            runners = [(label, lambda p=path: run_program(p, mesh, case, edit)) for label, path in programs]
            if obj and case in ("smoothest", "aligned"):
                runners.append(("fieldgen", lambda: run_fieldgen(a.anchors, obj, case)))
            results = {label: [] for label, _ in runners}
            for rep in range(a.reps):
                order = runners if rep % 2 == 0 else list(reversed(runners))
                for label, run in order:
                    results[label].append(run())
            first = statistics.median(t for t, _, _ in results[programs[0][0]])
            reference = statistics.median(t for t, _, _ in results["fieldgen"]) if "fieldgen" in results else None
            reference_mb = max(m for _, m, _ in results["fieldgen"]) if "fieldgen" in results else None
            for label, _ in runners:
                times = [t for t, _, _ in results[label]]
                peak = max(m for _, m, _ in results[label])
                print("%s | %s | %s | %s | %.2f | %s | %.0f | %s | %s" % (
                    os.path.basename(mesh), case, label, summary(times), statistics.median(times) / first,
                    "%.3f" % (statistics.median(times) / reference) if reference else "",
                    peak, "%.3f" % (peak / reference_mb) if reference_mb else "",
                    sorted({s for _, _, s in results[label]})), flush=True)


if __name__ == "__main__":
    main()
