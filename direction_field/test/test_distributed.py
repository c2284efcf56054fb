#!/usr/bin/env python3
"""The distributed solver (--solver petsc under mpirun) against the
single-process one: the same smallest eigenvalues (to 1e-8 relative) and the
same singular faces, for the smoothest field on meshes with several components
and with boundary, for the curvature-aligned and the boundary-constrained
fields, on 1, 2 and 4 processes, every component of at least 32 vertices per
process spread over the processes (--distribute-from 0; smaller ones, here a
single triangle, stay on the first process); and with the default
threshold, which leaves these small components to the first process. Then
the fields that LOBPCG alone does not finish: a dumbbell whose field is
eleven orders smaller on one end than on the other, an icosphere's nearly
equal smallest eigenvalues; 500 tetrahedra (components too small to spread);
and failures: refused options, processes out of memory or killed.

    usage: test_distributed.py DIRECTION_FIELD MPIEXEC SHARED_MESH_DIR OUTPUT_DIR
"""
import json
import math
import os
import shutil
import subprocess
import sys

from checks import MPI_ENVIRONMENT as ENV, Checks

BIN, MPIEXEC, SHARED, OUT = sys.argv[1:5]
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
check = Checks()


def run(mesh, options, ranks, tag, distribute_from="0"):
    sing = os.path.join(OUT, tag + ".sing")
    args = [BIN, mesh, "--json", "--singularities", sing] + options
    if ranks > 0:
        args = [MPIEXEC, "-np", str(ranks)] + args + ["--solver", "petsc"]
        if distribute_from is not None:
            args += ["--distribute-from", distribute_from]
    r = subprocess.run(args, capture_output=True, text=True, env=ENV, timeout=600)
    check(r.returncode == 0, "%s: status %d %r" % (tag, r.returncode, r.stderr[-500:]))
    if r.returncode != 0:
        return None, None
    return json.loads(r.stdout), open(sing).read()


# two components, one of them a single triangle; a triaxial ellipsoid, whose
# smallest eigenvalue is simple (a sphere's is not, and another solver may
# return another field of the same energy)
two_parts = os.path.join(OUT, "ellipsoid_and_triangle.off")
with open(two_parts, "w") as f:
    rings, points, faces = 12, [(0, 0, 0.6)], []
    for i in range(1, rings):
        for j in range(2 * rings):
            t, p = math.pi * i / rings, math.pi * j / rings
            points.append((math.sin(t) * math.cos(p), 0.8 * math.sin(t) * math.sin(p), 0.6 * math.cos(t)))
    points.append((0, 0, -0.6))
    south = len(points) - 1
    index = lambda i, j: 1 + (i - 1) * 2 * rings + j % (2 * rings)
    for j in range(2 * rings):
        faces += [(0, index(1, j), index(1, j + 1)), (south, index(rings - 1, j + 1), index(rings - 1, j))]
    for i in range(1, rings - 1):
        for j in range(2 * rings):
            a, b, c, d = index(i, j), index(i, j + 1), index(i + 1, j), index(i + 1, j + 1)
            faces += [(a, c, b), (b, c, d)]
    n = len(points)
    points += [(5, 0, 0), (6, 0, 0), (5, 1, 0)]
    faces.append((n, n + 1, n + 2))
    f.write("OFF\n%d %d 0\n" % (len(points), len(faces)) + "".join("%r %r %r\n" % p for p in points) +
            "".join("3 %d %d %d\n" % t for t in faces))

cases = [(two_parts, [], "smoothest")]
for name, options, what in [("bones.off", [], "smoothest"), ("plane_holes.off", [], "smoothest"),
                            ("fandisk.off", ["--align", "curvature"], "aligned"),
                            ("plane_holes.off", ["--constrain-boundary", "tangent"], "constrained")]:
    path = os.path.join(SHARED, name)
    if SHARED and os.path.exists(path):
        cases.append((path, options, what))
    else:
        check.skip("%s: no shared meshes" % name)

for mesh, options, what in cases:
    tag = os.path.basename(mesh) + "_" + what
    single, single_sing = run(mesh, options, 0, tag + "_single")
    for ranks in [1, 2, 4]:
        d, sing = run(mesh, options, ranks, "%s_np%d" % (tag, ranks))
        if single is None or d is None:
            continue
        check(d["solver"] == "petsc" and d["ranks"] == ranks, tag + ": solver and ranks in the JSON")
        # an aligned field computes lambda_1 with a solver that cannot tell an indefinite matrix (null otherwise);
        # a flat component's lambda_1 is 0 up to rounding (the single triangle: 1e-31 and -5e-16)
        same_values = all(a is None or b is None or abs(a - b) <= 1e-8 * abs(a) or abs(a - b) < 1e-12
                          for a, b in zip(single["eigenvalues"], d["eigenvalues"]))
        check(same_values, "%s np=%d: eigenvalues %s against %s" % (tag, ranks, d["eigenvalues"][:4],
                                                                 single["eigenvalues"][:4]))
        check(sing == single_sing and d["index_sum"] == single["index_sum"],
              "%s np=%d: the same singular faces" % (tag, ranks))

# PETSc's own options pass through (here: GAMG's threshold in the eigen-solve), with the same result
d, sing = run(two_parts, ["--petsc-options", "-st_pc_gamg_threshold 0.02"], 2, "petsc_options")
single, single_sing = run(two_parts, [], 0, "petsc_options_single")
check(d is not None and sing == single_sing, "--petsc-options: the same singular faces")

# the default threshold: the small components solved by the first process, the same result
d, sing = run(two_parts, [], 2, "default_threshold", distribute_from=None)
check(d is not None and sing == single_sing and d["eigenvalues"] == single["eigenvalues"],
      "default --distribute-from: the first process's solve, the same eigenvalues and singular faces")

def write_off(path, points, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(faces)) + "".join("%r %r %r\n" % p for p in points) +
                "".join("3 %d %d %d\n" % t for t in faces))


def surface_of_revolution(path, profile, segments):
    """profile: (radius, height) from pole to pole, the poles at radius 0"""
    points = [(0., 0., profile[0][1])]
    for r, z in profile[1:-1]:
        points += [(r * math.cos(2 * math.pi * j / segments), r * math.sin(2 * math.pi * j / segments), z)
                   for j in range(segments)]
    points.append((0., 0., profile[-1][1]))
    last, rings = len(points) - 1, len(profile) - 2
    index = lambda i, j: 1 + i * segments + j % segments
    faces = []
    for j in range(segments):
        faces += [(0, index(0, j), index(0, j + 1)), (last, index(rings - 1, j + 1), index(rings - 1, j))]
    for i in range(rings - 1):
        for j in range(segments):
            a, b, c, d = index(i, j), index(i, j + 1), index(i + 1, j), index(i + 1, j + 1)
            faces += [(a, c, b), (b, c, d)]
    write_off(path, points, faces)


def dumbbell(path, big=1., neck=0.1, length=6., small=0.7, steps=80, segments=64):
    """two spheres joined by a long thin neck: the smoothest field lives on the
    big one and falls by eleven orders of magnitude along the neck"""
    top = math.asin(neck / big)
    profile = [(big * math.sin(t), big * math.cos(t))
               for t in (math.pi - (math.pi - top) * k / steps for k in range(steps + 1))]
    start = big * math.cos(top)
    along = max(2, int(steps * length / (math.pi * big)))
    profile += [(neck, start + length * k / along) for k in range(1, along)]
    bottom = math.asin(neck / small)
    center = start + length + small * math.cos(bottom)
    profile += [(small * math.sin(t), center + small * math.cos(t))
                for t in (math.pi - bottom - (math.pi - bottom) * k / steps for k in range(steps + 1))]
    profile[0], profile[-1] = (0., profile[0][1]), (0., profile[-1][1])
    surface_of_revolution(path, profile, segments)


def icosphere(path, levels):
    t = (1 + 5 ** 0.5) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
              (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
             (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
             (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        middle, refined = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                middle[key] = len(points)
                points.append(tuple((p + q) / 2 for p, q in zip(points[a], points[b])))
            return middle[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            refined += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = refined
    points = [tuple(x / math.sqrt(sum(y * y for y in p)) for x in p) for p in points]
    write_off(path, points, faces)


# the dumbbell: vertices below the solve's accuracy, reported alike by both
# solvers (inverse iteration on a distributed factorization finishes the
# distributed solve), and the same singular faces
def determined_faces(ply, relative):
    """the faces of an ASCII PLY of --ply whose three vertices' magnitudes are
    at least `relative` times the largest"""
    with open(ply) as f:
        vertices = 0
        for line in f:
            if line.startswith("element vertex"):
                vertices = int(line.split()[2])
            if line.startswith("end_header"):
                break
        magnitude = [float(next(f).split()[6]) for _ in range(vertices)]
        largest = max(magnitude)
        kept = set()
        for face, line in enumerate(f):
            corners = [int(x) for x in line.split()[1:4]]
            if all(magnitude[v] >= relative * largest for v in corners):
                kept.add(face)
    return kept


def singular_set(text, faces=None):
    pairs = set(tuple(line.split()) for line in text.splitlines() if line.strip())
    return pairs if faces is None else set(p for p in pairs if int(p[0]) in faces)


bell = os.path.join(OUT, "dumbbell.off")
dumbbell(bell)
single, single_sing = run(bell, ["--ply", os.path.join(OUT, "dumbbell.ply")], 0, "dumbbell_single")
d, sing = run(bell, [], 2, "dumbbell_np2")
if single and d:
    low_1, low_2 = single["component_low_magnitude_fractions"][0], d["component_low_magnitude_fractions"][0]
    check(low_1 > 0.01 and abs(low_1 - low_2) < 0.002, "dumbbell: low-magnitude fractions %r and %r" % (low_1, low_2))
    check(d["converged"] and d["residual"] <= 1e-10, "dumbbell, 2 processes: converged (%r)" % d["residual"])
    # where the field is above the solve's accuracy, the same singular faces;
    # below it (here around both poles, where the field vanishes to 1e-10 of
    # its largest), the same number, not always the same faces
    kept = determined_faces(os.path.join(OUT, "dumbbell.ply"), 100 * 1e-10)
    check(singular_set(sing, kept) == singular_set(single_sing, kept) and len(kept) > 0.9 * 39808,
          "dumbbell: the same singular faces where the field is above the accuracy")
    check(d["singular_faces"] == single["singular_faces"] and d["index_sum"] == single["index_sum"],
          "dumbbell: %d and %d singular faces" % (single["singular_faces"], d["singular_faces"]))
# without the inverse iteration (-smdf_refinement_steps 0): still a result; a negative count: refused
d, _ = run(bell, ["--petsc-options", "-smdf_refinement_steps 0"], 2, "dumbbell_no_refinement")
check(d is not None and d["singular_faces"] == single["singular_faces"], "-smdf_refinement_steps 0: a result")
r = subprocess.run([MPIEXEC, "-np", "2", BIN, bell, "--solver", "petsc", "--distribute-from", "0",
                    "--petsc-options", "-smdf_refinement_steps -1"], capture_output=True, text=True, env=ENV, timeout=300)
check(r.returncode != 0 and "-smdf_refinement_steps must be at least 0 (got -1)" in r.stderr,
      "-smdf_refinement_steps -1: status %d, %r" % (r.returncode, r.stderr[:200]))

# an icosphere (nearly equal smallest eigenvalues, where LOBPCG crawls): converged, the same 8 singular faces
sphere = os.path.join(OUT, "icosphere.off")
icosphere(sphere, 4)
single, single_sing = run(sphere, [], 0, "icosphere_single")
d, sing = run(sphere, [], 2, "icosphere_np2")
check(d is not None and d["converged"] and d["singular_faces"] == single["singular_faces"] == 8,
      "icosphere, 2 processes: converged with 8 singular faces")

# 500 tetrahedra with every component asked to be spread: each is too small
# (fewer than 32 vertices per process), so the first process solves each
# alone, exactly as one process would
tetrahedra = os.path.join(OUT, "tetrahedra.off")
points, faces = [], []
for k in range(500):
    x, y, b = 3. * (k % 25), 3. * (k // 25), len(points)
    points += [(x, y, 0.), (x + 1, y, 0.), (x, y + 1, 0.), (x, y, 1.)]
    faces += [(b, b + 2, b + 1), (b, b + 1, b + 3), (b, b + 3, b + 2), (b + 1, b + 2, b + 3)]
write_off(tetrahedra, points, faces)
single, single_sing = run(tetrahedra, [], 0, "tetrahedra_single")
d, sing = run(tetrahedra, [], 2, "tetrahedra_np2")
check(d is not None and d["eigenvalues"] == single["eigenvalues"] and d["residual"] == single["residual"]
      and sing == single_sing, "500 tetrahedra, --distribute-from 0: the first process's solves, unchanged")

# an input the first process refuses: one error line and status 1, the other processes released (no hang)
r = subprocess.run([MPIEXEC, "-np", "2", BIN, os.path.join(OUT, "missing.off"), "--solver", "petsc"],
                   capture_output=True, text=True, env=ENV, timeout=120)
check(r.returncode != 0 and r.stderr.count("direction_field: error: cannot open") == 1,
      "a missing mesh under mpirun: status %d, %r" % (r.returncode, r.stderr[:200]))

# a bad option, which every process refuses before MPI starts: said once
r = subprocess.run([MPIEXEC, "-np", "2", BIN, two_parts, "--solver", "petsc", "--distribute-from", "-5"],
                   capture_output=True, text=True, env=ENV, timeout=120)
check(r.returncode != 0 and r.stderr.count("direction_field: error:") == 1,
      "a bad option under mpirun: status %d, %d error lines" % (r.returncode, r.stderr.count("direction_field: error:")))

# PETSc refusing an option inside a solve (petsc_calls.h): every process
# ends (no hang), the status is not 0, a failing process names the PETSc
# routine in one line, and no output is renamed into place
for petsc_options, extra, what in (("-st_pc_type nonsense", [], "the eigen-solve's preconditioner"),
                                   ("-ksp_type nonsense", ["--align", "curvature"], "the aligned solve's Krylov method")):
    for ranks in (1, 2):
        target = os.path.join(OUT, "refused_%d.txt" % ranks)
        r = subprocess.run([MPIEXEC, "-np", str(ranks), BIN, two_parts, "--solver", "petsc", "--distribute-from", "0",
                            "--directions", target, "--petsc-options", petsc_options] + extra,
                           capture_output=True, text=True, env=ENV, timeout=300)
        lines = [l for l in r.stderr.splitlines() if "PETSc failed in" in l]
        check(r.returncode != 0 and 1 <= len(lines) <= ranks and all(l.startswith("Surface_mesh_direction_fields: error on process") for l in lines)
              and not os.path.exists(target) and "Traceback" not in r.stderr and "[0]PETSC ERROR" not in r.stderr,
              "%s refused (%s), %d processes: status %d, lines %r" % (petsc_options, what, ranks, r.returncode, lines[:2]))

# what PETSc does at its end fails (-log_view into a missing folder): status
# 1, the program's one line, no JSON on stdout and no output renamed into place
for ranks in (1, 2):
    target = os.path.join(OUT, "log_view_%d.txt" % ranks)
    r = subprocess.run([MPIEXEC, "-np", str(ranks), BIN, two_parts, "--solver", "petsc", "--distribute-from", "0", "--json",
                        "--directions", target, "--petsc-options", "-log_view :" + os.path.join(OUT, "missing", "log")],
                       capture_output=True, text=True, env=ENV, timeout=300)
    check(r.returncode != 0 and r.stdout == "" and not os.path.exists(target)
          and r.stderr.count("direction_field: error: PETSc failed at its end") == 1,
          "-log_view that cannot write, %d processes: status %d, stdout %r, stderr %r" % (ranks, r.returncode, r.stdout[:80], r.stderr[:200]))

# a negative iteration limit of the linear solves, which PETSc takes and
# then stops at once: refused by name; a positive limit too small: the solve's
# failure, not the given lambda_t's (there is none)
plane_holes = os.path.join(SHARED, "plane_holes.off") if SHARED else ""
if os.path.exists(plane_holes):
    for ranks in (1, 2):
        for limit, expected in (("-5", "-ksp_max_it must be at least 1 (got -5)"),
                                ("2", "direction_field: error: the linear solve of component 0 did not converge")):
            r = subprocess.run([MPIEXEC, "-np", str(ranks), BIN, plane_holes, "--solver", "petsc", "--distribute-from", "0",
                                "--constrain-boundary", "tangent", "--petsc-options", "-ksp_max_it " + limit],
                               capture_output=True, text=True, env=ENV, timeout=300)
            check(r.returncode != 0 and expected in r.stderr and "alignment_lambda" not in r.stderr,
                  "-ksp_max_it %s, %d processes: status %d, %r" % (limit, ranks, r.returncode, r.stderr[:200]))
else:
    check.skip("-ksp_max_it: no shared meshes")


def launched_with(wrapper_body, tag):
    """A launcher script for mpirun: runs the program as the body says for
    the process of rank 1 (OMPI_COMM_WORLD_RANK, PMI_RANK), plainly for the others."""
    path = os.path.join(OUT, tag + ".sh")
    with open(path, "w") as f:
        f.write('#!/bin/sh\nrank="${OMPI_COMM_WORLD_RANK:-$PMI_RANK}"\n' + wrapper_body)
    os.chmod(path, 0o755)
    return path


# a process out of memory (an address-space limit on one rank) or killed
# mid-run: every process ends, the status is not 0, no output is renamed
# into place; out of memory is said in one line naming the process
large = os.path.join(SHARED, "nefertiti_sub4.off") if SHARED else ""
if os.path.exists(large):
    for limited_rank in ("0", "1"):
        failures = 0
        for megabytes in (350, 400, 500, 600, 700, 900, 1600):
            launcher = launched_with('if [ "$rank" = "%s" ]; then exec prlimit --as=%d "$@"; fi\nexec "$@"\n'
                                     % (limited_rank, megabytes * 1000000), "limit")
            target = os.path.join(OUT, "limited.txt")
            try:
                r = subprocess.run([MPIEXEC, "-np", "2", launcher, BIN, large, "--solver", "petsc", "--distribute-from", "0",
                                    "--json", "--directions", target], capture_output=True, text=True, env=ENV, timeout=240)
            except subprocess.TimeoutExpired:
                check(False, "rank %s limited to %d MB: no end in 240 s" % (limited_rank, megabytes))
                continue
            said = [l for l in r.stderr.splitlines() if "out of memory" in l]
            if r.returncode == 0:
                check(json.loads(r.stdout)["singular_faces"] > 0 and os.path.exists(target),
                      "rank %s limited to %d MB: a result" % (limited_rank, megabytes))
            else:
                failures += 1
                check(r.stdout == "" and not os.path.exists(target) and len(said) == 1,
                      "rank %s limited to %d MB: status %d, lines %r" % (limited_rank, megabytes, r.returncode, said))
            if os.path.exists(target):
                os.remove(target)
        check(failures > 0, "rank %s: some limit too small for the run (the sweep reaches the failing paths)" % limited_rank)
    target = os.path.join(OUT, "killed.txt")
    for seconds in ("0.5", "1.2", "1.8"):
        launcher = launched_with('if [ "$rank" = "1" ]; then exec timeout -s KILL %s "$@"; fi\nexec "$@"\n' % seconds,
                                 "kill")
        try:
            r = subprocess.run([MPIEXEC, "-np", "2", launcher, BIN, large, "--solver", "petsc", "--distribute-from", "0",
                                "--json", "--directions", target], capture_output=True, text=True, env=ENV, timeout=240)
            check(r.returncode != 0 and r.stdout == "" and not os.path.exists(target),
                  "rank 1 killed after %s s: status %d, stdout %r" % (seconds, r.returncode, r.stdout[:80]))
        except subprocess.TimeoutExpired:
            check(False, "rank 1 killed after %s s: no end in 240 s" % seconds)
else:
    check.skip("a process out of memory or killed: no shared meshes")

check.finish()
