#!/usr/bin/env python3
"""The default job of direction_field under a sweep of address-space limits.

Every run must end within its time limit with either a result (exit 0, the
field file written) or exit 1 and exactly one line on stderr naming the
problem: never a hang (OpenBLAS's allocator retries forever when its work
buffers cannot be mapped; dense_kernels.h says how the package avoids it),
a signal or a partial output file. The BLAS keeps its default number of
threads (the hang needs more than one).

    usage: test_memory_limits.py DIRECTION_FIELD MESH_DIR OUTPUT_DIR
"""
import os
import resource
import shutil
import subprocess
import sys

from checks import Checks

BIN, MESHES, OUT = sys.argv[1], sys.argv[2], sys.argv[3]
if os.environ.get("SMDF_NO_MEMORY_LIMIT") == "1":  # AddressSanitizer: no limit can apply
    print("SKIPPED: no address-space limit under the sanitizers")
    sys.exit(77)
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
check = Checks()
TIME_LIMIT = 120


def run_limited(mesh, megabytes, options=(), output="--directions"):
    limit = megabytes << 20
    out = os.path.join(OUT, "%s_%d%s%s" % (os.path.splitext(os.path.basename(mesh))[0], megabytes,
                                           "_prescribed" if options else "", output.replace("-", "_")))
    env = dict(os.environ)
    env.pop("OPENBLAS_NUM_THREADS", None)
    try:
        r = subprocess.run([BIN, mesh, output, out + ".txt", "--quiet"] + list(options),
                           capture_output=True, text=True,
                           timeout=TIME_LIMIT, env=env,
                           preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_AS, (limit, limit)))
    except subprocess.TimeoutExpired:
        check(False, "%s at %d MB: no end within %d s" % (mesh, megabytes, TIME_LIMIT))
        return None
    lines = r.stderr.strip().splitlines()
    if r.returncode == 0:
        check(os.path.getsize(out + ".txt") > 0, "%s at %d MB: a result, the field written" % (mesh, megabytes))
    else:
        check(r.returncode == 1 and len(lines) == 1 and lines[0].startswith("direction_field: error:")
              and not os.path.exists(out + ".txt"),
              "%s at %d MB: exit 1 with one line and no output (exit %d, stderr %r)"
              % (mesh, megabytes, r.returncode, r.stderr[-300:]))
    return r.returncode


meshes = [m for m in (os.path.join(MESHES, "fandisk.off"), os.path.join(MESHES, "nefertiti.off")) if MESHES and os.path.exists(m)]
if not meshes:
    print("SKIPPED: the shared meshes are not there")
    sys.exit(77)
outcomes = []
for mesh in meshes:
    # (below about 150 MB the dynamic loader itself cannot map the libraries)
    for megabytes in (160, 200, 250, 300, 350, 400, 500, 600, 800, 1200):
        outcomes.append((mesh, megabytes, run_limited(mesh, megabytes)))
# placing the smoothest field's own singularities (a CHOLMOD factorization of
# the vertex Laplacian, which calls the BLAS): the same discipline, no hang
nefertiti = os.path.join(MESHES, "nefertiti.off")
if os.path.exists(nefertiti):
    listing = os.path.join(OUT, "nefertiti.sing")
    subprocess.run([BIN, nefertiti, "--singularities", listing, "--quiet"], check=True, capture_output=True)
    for megabytes in (200, 300, 380, 440, 500, 550, 650, 1200):
        outcomes.append((nefertiti, megabytes, run_limited(nefertiti, megabytes, ["--prescribe", listing])))
    # the same on faces: the face field's singular vertices placed again (a CHOLMOD factorization of the
    # faces' Laplacian, whose factor is allocated before the BLAS takes its buffers)
    listing = os.path.join(OUT, "nefertiti_faces.sing")
    subprocess.run([BIN, nefertiti, "--on", "faces", "--sing", listing, "--quiet"], check=True, capture_output=True)
    vertices = os.path.join(OUT, "nefertiti_faces.asked")
    with open(vertices, "w") as f:
        f.write("\n".join(open(listing).read().splitlines()[1:]) + "\n")
    for megabytes in (200, 300, 380, 440, 500, 550, 650, 1200):
        outcomes.append((nefertiti, megabytes, run_limited(nefertiti, megabytes, ["--on", "faces", "--prescribe", vertices],
                                                           output="--rawfield")))
# the largest limit is enough for both meshes: the sweep covers both outcomes
check(all(code == 0 for (_, mb, code) in outcomes if mb == 1200), "every mesh computes with 1200 MB")
check(any(code == 1 for (_, _, code) in outcomes), "some limit is too small (the error path is exercised)")
for mesh, megabytes, code in outcomes:
    print("%s %d MB: %s" % (os.path.basename(mesh), megabytes, {0: "result", 1: "error", None: "hang"}.get(code, "exit %s" % code)))
check.finish()
