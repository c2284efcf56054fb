"""The program built against two CGAL releases (Debian's 5.5 and 6.1) writes
the same files, byte for byte, on every shared mesh: the smoothest cross
field, and a curvature-aligned line field along sharp features. Prints a
table of checksums (one row per mesh and field). Exit 77 (skipped) without
the shared meshes.

usage: test_same_outputs_across_cgal.py PROGRAM_A PROGRAM_B SHARED_MESH_DIR OUTPUT_DIR
"""
import hashlib
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402

FIELDS = {
    "cross": ["--degree", "4"],
    "aligned_lines": ["--degree", "2", "--align", "curvature", "--feature-angle", "40"],
}
# every output that does not hold timings (the JSON and the summary do)
OUTPUTS = ["directions.txt", "singularities.txt", "field.vtu", "field.ply", "markers.vtu", "lines.vtu",
           "mesh.off", "singularity_list.txt", "picture.png"]
OPTIONS = ["--directions", "--singularities", "--vtk", "--ply", "--vtk-singularities", "--streamlines",
           "--mesh-out", "--singularity-list", "--png"]


def run(program, mesh, field, folder):
    os.makedirs(folder, exist_ok=True)
    command = [program, mesh, "--quiet"] + FIELDS[field]
    for option, name in zip(OPTIONS, OUTPUTS):
        command += [option, os.path.join(folder, name)]
    result = subprocess.run(command, capture_output=True, text=True, timeout=600,
                            env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
    return result.returncode, result.stderr.strip()


def digest(path):
    """The file's sha256, or "absent" (a .vtu with nothing to show is left out)."""
    if not os.path.exists(path):
        return "absent"
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()[:12]


def main():
    program_a, program_b, shared, out = sys.argv[1:5]
    if not shared or not os.path.isdir(shared):
        print("SKIPPED: no shared mesh folder")
        sys.exit(77)
    shutil.rmtree(out, ignore_errors=True)
    check = Checks()
    meshes = sorted(name for name in os.listdir(shared) if name.endswith(".off"))
    print("%-24s %-14s %s" % ("mesh", "field", "sha256 (first 12) of " + ", ".join(OUTPUTS)))
    for name in meshes:
        for field in FIELDS:
            folders = [os.path.join(out, tag, name, field) for tag in ("a", "b")]
            runs = [run(program, os.path.join(shared, name), field, folder)
                    for program, folder in zip((program_a, program_b), folders)]
            if not check(runs[0] == runs[1], "%s %s: the same exit status and messages: %r" % (name, field, runs)):
                continue
            if runs[0][0] != 0:
                print("%-24s %-14s refused by both: %s" % (name, field, runs[0][1]))
                continue
            sums = [[digest(os.path.join(folder, o)) for o in OUTPUTS] for folder in folders]
            same = sums[0] == sums[1]
            check(same, "%s %s: the same files (%s)" % (
                name, field, [o for o, x, y in zip(OUTPUTS, sums[0], sums[1]) if x != y]))
            print("%-24s %-14s %s %s" % (name, field, " ".join(sums[0]), "same" if same else "DIFFERENT"))
    check.finish()


if __name__ == "__main__":
    main()
