#!/usr/bin/env python3
"""Fields on faces and features under hostile conditions (issue 72 of the
project): coordinates at any scale, prescriptions of large indices read back
from the files, closed standard streams, errors that name the file's line.

Every mesh is generated here: a box (its twelve edges sharp), a torus and a
grid. The scale sweep multiplies the coordinates by powers of ten up to
1e+-300; the features and the face field must not change, and every
direction written must be finite and of unit length. A prescription is read
back from .rawfield and .matching as Directional reads them: the rotation of
each direction across an edge taken in (-pi, pi], summed around each vertex
with n times its angle defect.

    usage: test_hostile_faces.py DIRECTION_FIELD OUTPUT_DIR
"""
import json
import math
import os
import resource
import shutil
import subprocess
import sys

from checks import Checks

BIN, OUT = sys.argv[1], sys.argv[2]
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
check = Checks()


def run(args, **kw):
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    return subprocess.run([BIN] + args, capture_output=True, text=True, timeout=120, env=env, **kw)


def write_off(name, points, faces, factor=1.0):
    path = os.path.join(OUT, name)
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        f.write("".join("%r %r %r\n" % tuple(factor * x for x in p) for p in points))
        f.write("".join("3 %d %d %d\n" % t for t in faces))
    return path


def box(k=6):
    """The surface of the cube [-1, 1]^3, each side a k x k grid of squares cut in two (chi = 2), the points
    moved within their sides (along the edges on an edge, the corners fixed) by a fixed pattern: no
    symmetry, so its fields are unique and do not depend on the rounding."""
    index, points, faces = {}, [], []

    def vertex(p):
        key = tuple(round(x * k) for x in p)
        if key not in index:
            index[key] = len(points)
            points.append(tuple(float(x) for x in p))
        return index[key]
    for axis in range(3):
        for side in (-1.0, 1.0):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            for i in range(k):
                for j in range(k):
                    quad = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [0.0, 0.0, 0.0]
                        p[axis], p[u], p[v] = side, -1 + 2.0 * (i + di) / k, -1 + 2.0 * (j + dj) / k
                        quad.append(vertex(p))
                    if side < 0:
                        quad.reverse()
                    faces += [(quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])]
    moved = [tuple(x if abs(x) == 1.0 else x + 0.3 / k * math.sin(12.9898 * i + 78.233 * c) for c, x in enumerate(p))
             for i, p in enumerate(points)]
    return moved, faces


def torus(m=24, n=12, big=2.0, small=0.7):
    """A torus of m x n vertices (chi = 0), vertex i * n + j."""
    points = [((big + small * math.cos(2 * math.pi * j / n)) * math.cos(2 * math.pi * i / m),
               (big + small * math.cos(2 * math.pi * j / n)) * math.sin(2 * math.pi * i / m),
               small * math.sin(2 * math.pi * j / n)) for i in range(m) for j in range(n)]
    faces = []
    for i in range(m):
        for j in range(n):
            a, b = i * n + j, ((i + 1) % m) * n + j
            c, d = ((i + 1) % m) * n + (j + 1) % n, i * n + (j + 1) % n
            faces += [(a, b, c), (a, c, d)]
    return points, faces


def numbers(path):
    return [float(x) for x in open(path).read().split()]


def rawfield_units(path, n):
    """Whether every direction of a .rawfield is finite and of unit length."""
    values = numbers(path)[2:]
    vectors = [values[i:i + 3] for i in range(0, len(values), 3)]
    return len(vectors) > 0 and all(all(math.isfinite(x) for x in v) and abs(math.sqrt(sum(x * x for x in v)) - 1) < 1e-12
                                    for v in vectors)


# ---------------------------------------------------------------- features and face files at any scale
FACTORS = [1.0, 1e155, 1e-200, 1e300, 1e-300]
points, faces = box()
on_faces, on_vertices = {}, {}
for factor in FACTORS:
    mesh = write_off("box_%g.off" % factor, points, faces, factor)
    prefix = os.path.join(OUT, "box_%g" % factor)
    r = run([mesh, "--on", "faces", "--feature-angle", "35", "--json", "--sing", prefix + ".sing",
             "--sharp", prefix + ".sharp", "--rawfield", prefix + ".rawfield", "--rosy", prefix + ".rosy"])
    if check(r.returncode == 0, "box x %g on faces with features: %r" % (factor, r.stderr[-300:])):
        d = json.loads(r.stdout)
        on_faces[factor] = (open(prefix + ".sing").read(), open(prefix + ".sharp").read())
        check(d["index_sum"] + d["boundary_index"] == 4 * d["euler_characteristic"],
              "box x %g on faces: Poincare-Hopf" % factor)
        check(rawfield_units(prefix + ".rawfield", 4), "box x %g: every .rawfield direction finite and unit" % factor)
        check(all(math.isfinite(x) for x in numbers(prefix + ".rosy")), "box x %g: .rosy finite" % factor)
    listing = prefix + ".list"
    r = run([mesh, "--feature-angle", "35", "--json", "--singularity-list", listing])
    if check(r.returncode == 0, "box x %g on vertices with features: %r" % (factor, r.stderr[-300:])):
        d = json.loads(r.stdout)
        on_vertices[factor] = [line.split()[:2] for line in open(listing) if not line.startswith("#")]
        check(d["index_sum"] == 4 * 2, "box x %g on vertices with features: index sum %d = n chi" % (factor, d["index_sum"]))
sharp_lines = int(on_faces[1.0][1].split()[0]) if 1.0 in on_faces else 0
check(sharp_lines == 12 * 6 * 2, "the box's 12 edges of 6 sides are sharp, each side of each face listed (%d)" % sharp_lines)
for factor in FACTORS[1:]:
    check(on_faces.get(factor) == on_faces.get(1.0), "box x %g: the same .sing and .sharp as unscaled" % factor)
    check(on_vertices.get(factor) == on_vertices.get(1.0), "box x %g: the same singular faces on vertices" % factor)

# a face field at extreme scales without features: unit directions, the same singular vertices
t_points, t_faces = torus()
sing = {}
for factor in [1.0, 1e300, 1e-300, 1e-200]:
    mesh = write_off("torus_%g.off" % factor, t_points, t_faces, factor)
    prefix = os.path.join(OUT, "torus_%g" % factor)
    r = run([mesh, "--on", "faces", "--quiet", "--rawfield", prefix + ".rawfield", "--sing", prefix + ".sing",
             "--ffield", prefix + ".ffield"])
    if check(r.returncode == 0, "torus x %g on faces: %r" % (factor, r.stderr[-300:])):
        check(rawfield_units(prefix + ".rawfield", 4), "torus x %g: every .rawfield direction finite and unit" % factor)
        check("nan" not in open(prefix + ".ffield").read().lower(), "torus x %g: no NaN in .ffield" % factor)
        sing[factor] = open(prefix + ".sing").read()
check(len(set(sing.values())) == 1 and len(sing) == 4, "torus: the same singular vertices at every scale")


# ---------------------------------------------------------------- prescriptions read back as Directional reads them
def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def unit(a):
    length = math.sqrt(dot(a, a))
    return [x / length for x in a]


def read_back_indices(points, faces, prefix, n):
    """Each interior vertex's k from .rawfield and .matching: Directional's effort (each direction's rotation
    to its matched one across the edge, after the transport that unfolds the two faces, in (-pi, pi]) summed
    around the vertex, plus n times its angle defect, over 2 pi."""
    raw = numbers(prefix + ".rawfield")[2:]
    direction = [[raw[3 * (n * f + j):3 * (n * f + j) + 3] for j in range(n)] for f in range(len(faces))]
    normal = [unit(cross(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]]))) for t in faces]
    m = open(prefix + ".matching").read().split()
    turn = [0.0] * len(points)
    for e in range(int(m[1])):
        f, g, a, b, jump = map(int, m[3 + 5 * e:8 + 5 * e])
        if g < 0:
            continue
        along = unit(sub(points[b], points[a]))
        effort = 0.0
        for j in range(n):
            v = direction[f][j]
            alpha, beta = dot(v, along), dot(v, cross(normal[f], along))
            moved = [alpha * along[i] + beta * cross(normal[g], along)[i] for i in range(3)]
            w = direction[g][(j + jump) % n]
            effort += math.atan2(dot(cross(moved, w), normal[g]), dot(moved, w))
        turn[b] += effort  # from f to g is counter-clockwise about b
        turn[a] -= effort
    angles = [0.0] * len(points)
    for t in faces:
        for c in range(3):
            p, q, r = points[t[c]], points[t[(c + 1) % 3]], points[t[(c + 2) % 3]]
            angles[t[c]] += math.acos(max(-1.0, min(1.0, dot(unit(sub(q, p)), unit(sub(r, p))))))
    return {v: round((turn[v] + n * (2 * math.pi - angles[v])) / (2 * math.pi)) for v in range(len(points))}


def prescribed_case(name, asked):
    mesh = write_off("torus_1.off", t_points, t_faces)
    prefix = os.path.join(OUT, name)
    with open(prefix + ".asked", "w") as f:
        f.write("".join("%d %d\n" % vk for vk in asked.items()))
    args = [mesh, "--on", "faces", "--quiet", "--prescribe", prefix + ".asked", "--rawfield", prefix + ".rawfield",
            "--matching", prefix + ".matching", "--sing", prefix + ".sing"]
    return prefix, run(args)


# the reader itself: on the smoothest field it finds the .sing's vertices
prefix = os.path.join(OUT, "torus_1")
r = run([os.path.join(OUT, "torus_1.off"), "--on", "faces", "--quiet", "--rawfield", prefix + ".rawfield",
         "--matching", prefix + ".matching", "--sing", prefix + ".sing"])
got = {v: k for v, k in read_back_indices(t_points, t_faces, prefix, 4).items() if k != 0}
listed = open(prefix + ".sing").read().split()[2:]
check(got == {int(listed[i]): int(listed[i + 1]) for i in range(0, len(listed), 2)},
      "the read-back of the smoothest field finds the .sing's vertices: %r" % got)
# index 2 and -2 apart; +1 and -1, and +2 and -2, at the two ends of one edge: every one read back exactly
for name, asked in [("index_two", {0: 8, 150: -8}), ("adjacent_pair", {40: 4, 41: -4}),
                    ("adjacent_two", {60: 8, 61: -8})]:
    prefix, r = prescribed_case(name, asked)
    if check(r.returncode == 0, "%s: %r" % (name, r.stderr[-300:])):
        got = {v: k for v, k in read_back_indices(t_points, t_faces, prefix, 4).items() if k != 0}
        check(got == asked, "%s: .rawfield and .matching read back give %r, prescribed %r" % (name, got, asked))
# an index no edge of a fan of six can carry (each direction would turn by more than half a turn): one line
prefix, r = prescribed_case("index_ten", {0: 40, 150: -40})
check(r.returncode == 1 and r.stderr.count("\n") == 1 and "half a turn" in r.stderr,
      "index 10 on a valence-6 vertex: refused in one line (%d %r)" % (r.returncode, r.stderr))
check(not os.path.exists(prefix + ".rawfield"), "index 10: no .rawfield written")

# ---------------------------------------------------------------- a prescribed boundary vertex: the file's line
grid_points = [(i, j, 0.1 * ((i * 7 + j * 3) % 5)) for j in range(6) for i in range(6)]
grid_faces = []
for j in range(5):
    for i in range(5):
        a = 6 * j + i
        grid_faces += [(a, a + 1, a + 7), (a, a + 7, a + 6)]
grid = write_off("grid.off", grid_points, grid_faces)
asked = os.path.join(OUT, "boundary.asked")
with open(asked, "w") as f:
    f.write("14 1\n0 -1\n")
r = run([grid, "--on", "faces", "--prescribe", asked])
check(r.returncode == 1 and r.stderr.count("\n") == 1 and "line 2 of '%s'" % asked in r.stderr and
      "vertex 0" in r.stderr and "boundary" in r.stderr,
      "a boundary vertex in a face prescription: the file and its line (%r)" % r.stderr)

# ---------------------------------------------------------------- closed standard streams
# with standard error closed, a warning (the eigen-solve stopped early) must not land in an output file
directions = os.path.join(OUT, "closed_stderr.txt")
r = subprocess.run([BIN, os.path.join(OUT, "torus_1.off"), "--max-iterations", "1", "--directions", directions,
                    "--quiet"], capture_output=False, stdout=subprocess.DEVNULL, timeout=120,
                   preexec_fn=lambda: os.close(2))
lines = open(directions).read().splitlines() if os.path.exists(directions) else []
check(r.returncode == 0 and len(lines) == len(t_points) and all(len(l.split()) == 3 for l in lines) and
      "warning" not in "".join(lines), "standard error closed: the directions file holds directions only")
rosy = os.path.join(OUT, "closed_stderr.rosy")
r = subprocess.run([BIN, os.path.join(OUT, "torus_1.off"), "--on", "faces", "--max-iterations", "1", "--rosy", rosy,
                    "--quiet"], stdout=subprocess.DEVNULL, timeout=120, preexec_fn=lambda: os.close(2))
text = open(rosy).read() if os.path.exists(rosy) else "warning"
check(r.returncode == 0 and "warning" not in text and text.split()[0] == str(len(t_faces)),
      "standard error closed: the .rosy file holds the field only")
# with standard output closed the summary cannot be written: an error, and no output file is left
directions = os.path.join(OUT, "closed_stdout.txt")
r = subprocess.run([BIN, os.path.join(OUT, "torus_1.off"), "--directions", directions], capture_output=False,
                   stderr=subprocess.PIPE, text=True, timeout=120, preexec_fn=lambda: os.close(1))
check(r.returncode == 1 and "standard output" in r.stderr and not os.path.exists(directions),
      "standard output closed: refused (%d %r)" % (r.returncode, r.stderr))

# ---------------------------------------------------------------- a small limit of processes (ulimit -u)
# It binds only other users than root: run as nobody, with one BLAS thread (OpenBLAS starts its own pool
# when loaded). Where the program cannot start its threads it says so in one line of its own.
def as_nobody_with_process_limit(count):
    def start():
        os.setgid(65534)
        os.setuid(65534)
        resource.setrlimit(resource.RLIMIT_NPROC, (count, count))
    return start


if os.geteuid() == 0 and os.access(BIN, os.X_OK):
    tetrahedron = write_off("tetrahedron.off", [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)],
                            [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])
    os.chmod(OUT, 0o755)
    os.chmod(tetrahedron, 0o644)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    r = subprocess.run([BIN, tetrahedron, "--json"], capture_output=True, text=True, timeout=120, env=env,
                       preexec_fn=as_nobody_with_process_limit(1))
    check(r.returncode == 1 and r.stderr.count("\n") == 1 and "direction_field: error: cannot start" in r.stderr,
          "a limit of one process: one line of the program's own (%d %r)" % (r.returncode, r.stderr))
    r = subprocess.run([BIN, tetrahedron, "--json"], capture_output=True, text=True, timeout=120, env=env,
                       preexec_fn=as_nobody_with_process_limit(1000))
    check(r.returncode == 0 and json.loads(r.stdout)["index_sum"] == 8,
          "a limit of 1000 processes: the field (%d %r)" % (r.returncode, r.stderr))
else:
    print("the process limit is not checked: not root, or the program is not executable")

# ---------------------------------------------------------------- no huge-pages rerun in secure mode
# A setuid copy of the program started by another user runs in glibc's secure mode, where glibc ignores
# (newer glibc removes) GLIBC_TUNABLES: a rerun would run again and again. It must not rerun at all.
if os.geteuid() == 0:
    k = 400
    grid_points = [(i / (k - 1), j / (k - 1), 0.1 * math.sin(3.0 * i / k) * math.cos(2.0 * j / k + i / k))
                   for j in range(k) for i in range(k)]
    grid_faces = []
    for j in range(k - 1):
        for i in range(k - 1):
            a = j * k + i
            grid_faces += [(a, a + 1, a + k + 1), (a, a + k + 1, a + k)]
    big = write_off("grid_4mb.off", grid_points, grid_faces)
    os.chmod(big, 0o644)
    setuid_copy = os.path.join(OUT, "direction_field_setuid")
    shutil.copy(BIN, setuid_copy)
    os.chmod(setuid_copy, 0o4755)
    env = {k: v for k, v in os.environ.items() if k != "GLIBC_TUNABLES"}
    try:
        r = subprocess.run([setuid_copy, big, "--json", "--huge-pages", "on"], capture_output=True, text=True,
                           timeout=120, env=env, preexec_fn=as_nobody_with_process_limit(1000))
        check(os.path.getsize(big) >= 4 << 20 and r.returncode == 0 and json.loads(r.stdout)["huge_pages"] is False,
              "secure mode: no rerun, the field (%d %r)" % (r.returncode, r.stderr[-200:]))
    except subprocess.TimeoutExpired:
        check(False, "secure mode: the program does not end")

check.finish()
