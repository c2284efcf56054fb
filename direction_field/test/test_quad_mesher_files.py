#!/usr/bin/python3
"""The files of a field on faces (--on faces) read by the programs that use them.

vcglib's loaders, as QuadWild calls them (vcglib_field_reader, compiled
against ../shared/clients/vcglib), read --mesh-out and --rosy and must find
exactly the package's singular interior vertices, with vcglib's mismatch equal
to -k modulo 4; the .sharp lines must name the boundary edges and the edges
whose faces meet more than --feature-angle from flat, once per side, with the
convex/concave type of their dihedral angle. Directional's three files
(.rawfield, .sing, .matching) are read back by a small parser: n unit
tangent directions per face turning by 2 pi / n, the first one the .rosy's,
the matching closing around every interior vertex to its index modulo n, and
discrete Poincare-Hopf (interior indices plus the boundary's contribution).

    usage: test_quad_mesher_files.py DIRECTION_FIELD VCGLIB_READER SHARED_MESH_DIR OUTPUT_DIR
Exit status 77 (skipped) when the reader or the shared meshes are missing.
"""
import json
import math
import os
import shutil
import subprocess
import sys

from checks import Checks

BIN, READER, SHARED, OUT = sys.argv[1:5]
if not os.path.exists(READER) or not SHARED or not os.path.isdir(SHARED):
    print("SKIPPED: missing input: vcglib reader (../shared/clients/vcglib) or ../shared/data/meshes")
    sys.exit(77)
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
check = Checks()


def read_obj(path):
    points, faces = [], []
    for line in open(path):
        t = line.split()
        if t and t[0] == "v":
            points.append(tuple(map(float, t[1:4])))
        elif t and t[0] == "f":
            faces.append(tuple(int(x.split("/")[0]) - 1 for x in t[1:4]))
    return points, faces


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def unit(a):
    n = math.sqrt(dot(a, a))
    return (a[0] / n, a[1] / n, a[2] / n) if n > 0 else a


def face_normal(points, t):
    return unit(cross(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]])))


def sides_of_edges(faces):
    sides = {}
    for f, t in enumerate(faces):
        for c in range(3):
            a, b = t[c], t[(c + 1) % 3]
            sides.setdefault((min(a, b), max(a, b)), []).append((f, c))
    return sides


def cleaned_up(sharp, border, points, steps=4):
    """QuadWild's erosion and dilation of its features, as --feature-cleanup does it: `steps` times the edges
    at a free end (one sharp edge, not on the boundary) go, unless longer than 5% of the bounding box's
    diagonal; then `steps` times those touching a free end that was no junction come back."""
    low = [min(p[i] for p in points) for i in range(3)]
    high = [max(p[i] for p in points) for i in range(3)]
    longest = 0.05 * math.sqrt(sum((h - l) ** 2 for h, l in zip(high, low)))

    def count(edges):
        c = {}
        for a, b in edges:
            c[a] = c.get(a, 0) + 1
            c[b] = c.get(b, 0) + 1
        return c

    def free(c, v):
        return c.get(v, 0) == 1 and v not in border
    sharp = thinned(sharp, points, longest, 2 * steps)
    first = count(sharp)
    junction = {v for v, k in first.items() if k > 2 or (v in border and k > 0)}
    kept = set(sharp)
    for _ in range(steps):
        c = count(kept)
        kept = {(a, b) for a, b in kept if math.dist(points[a], points[b]) > longest or not (free(c, a) or free(c, b))}
    for _ in range(steps):
        c = count(kept)
        kept |= {(a, b) for a, b in sharp if (free(c, a) and a not in junction) or (free(c, b) and b not in junction)}
    return kept


def thinned(sharp, points, longest, length):
    """--feature-cleanup's thinning: the least sharp edge (largest cosine of the dihedral angle; ties by the
    vertex pair) of each cycle of at most `length` sharp edges goes, one at a time, unless it is long."""
    at = {}
    for key in sharp:
        for v in key:
            at.setdefault(v, []).append(key)
    kept = set(sharp)

    def joined(a, b, skipped):
        front, seen = [a], {a}
        for _ in range(length - 1):
            following = []
            for v in front:
                for key in at[v]:
                    if key == skipped or key not in kept:
                        continue
                    u = key[0] if key[1] == v else key[1]
                    if u == b:
                        return True
                    if u not in seen:
                        seen.add(u)
                        following.append(u)
            front = following
        return False
    for key in sorted((k for k in sharp if math.dist(points[k[0]], points[k[1]]) <= longest),
                      key=lambda k: (-sharp[k], k)):
        if joined(key[0], key[1], key):
            kept.discard(key)
    return kept


def expected_sharp(points, faces, angle):
    """(face, edge, type) of every side of a boundary edge or of an edge sharper than `angle`, cleaned up."""
    lines = set()
    sides = sides_of_edges(faces)
    border = {v for key, s in sides.items() if len(s) == 1 for v in key}
    sharp = {}  # edge -> the cosine of its dihedral angle
    for key, s in sides.items():
        if len(s) == 1:
            lines.add((s[0][0], s[0][1], 1))
        elif len(s) == 2 and angle is not None:
            (f, c), (g, d) = s
            nf, ng = face_normal(points, faces[f]), face_normal(points, faces[g])
            if dot(nf, ng) < math.cos(math.radians(angle)):
                sharp[key] = dot(nf, ng)
    for key in cleaned_up(sharp, border, points):
        (f, c), (g, d) = sides[key]
        nf, ng = face_normal(points, faces[f]), face_normal(points, faces[g])
        along = sub(points[faces[f][(c + 1) % 3]], points[faces[f][c]])
        convex = 1 if dot(cross(nf, ng), along) >= 0 else 0
        lines.add((f, c, convex))
        lines.add((g, d, convex))
    return lines


def check_directional_files(name, prefix, points, faces, n, data):
    raw = open(prefix + ".rawfield").read().split()
    check(int(raw[0]) == n and int(raw[1]) == len(faces), name + ": rawfield header")
    values = list(map(float, raw[2:]))
    rosy = list(map(float, open(prefix + ".rosy").read().split()[2:]))
    bad = 0
    for f, t in enumerate(faces):
        normal = face_normal(points, t)
        vectors = [values[3 * (n * f + k):3 * (n * f + k) + 3] for k in range(n)]
        if max(abs(vectors[0][i] - rosy[3 * f + i]) for i in range(3)) > 1e-12:
            bad += 1
        for k, v in enumerate(vectors):
            turn = math.atan2(dot(cross(vectors[0], v), normal), dot(vectors[0], v))
            if abs(dot(v, v) - 1) > 1e-12 or abs(dot(v, normal)) > 1e-9 or \
               abs(math.remainder(turn - 2 * math.pi * k / n, 2 * math.pi)) > 1e-9:
                bad += 1
    check(bad == 0, "%s: %d raw field directions are not the .rosy's turned by 2 pi k / n" % (name, bad))
    sing = open(prefix + ".sing").read().split()
    check(int(sing[0]) == n and int(sing[1]) == (len(sing) - 2) // 2, name + ": sing header")
    index = {int(sing[i]): int(sing[i + 1]) for i in range(2, len(sing), 2)}
    check(sum(index.values()) == data["index_sum"] and len(index) == data["singular_vertices"],
          name + ": the .sing file holds the JSON's singular vertices")
    check(data["index_sum"] + data["boundary_index"] == n * data["euler_characteristic"],
          name + ": interior indices %d + boundary %d = n chi %d" %
          (data["index_sum"], data["boundary_index"], n * data["euler_characteristic"]))
    m = open(prefix + ".matching").read().split()
    degree, ne, nf = int(m[0]), int(m[1]), int(m[2])
    check(degree == n and nf == len(faces), name + ": matching header")
    turns = {}  # the matching summed counter-clockwise around each vertex
    bad_edges = 0
    for e in range(ne):
        f, g, a, b, jump = map(int, m[3 + 5 * e:8 + 5 * e])
        if a not in faces[f] or faces[f][(faces[f].index(a) + 1) % 3] != b or not 0 <= jump < n:
            bad_edges += 1
        if g < 0:
            continue
        turns[b] = turns.get(b, 0) + jump  # from f to g is counter-clockwise about b
        turns[a] = turns.get(a, 0) - jump
    check(bad_edges == 0, "%s: %d edges do not run from a to b in their first face or have a matching outside "
                          "0 ... n - 1" % (name, bad_edges))
    border = {v for key, s in sides_of_edges(faces).items() if len(s) == 1 for v in key}
    bad = [v for v in turns if v not in border and (turns[v] - index.get(v, 0)) % n != 0]
    check(not bad, "%s: the matching around %d interior vertices does not close to their index" % (name, len(bad)))


def run_case(name, mesh, extra, n=4):
    prefix = os.path.join(OUT, name)
    files = ["--rosy", prefix + ".rosy", "--mesh-out", prefix + ".obj", "--sharp", prefix + ".sharp",
             "--rawfield", prefix + ".rawfield", "--sing", prefix + ".sing", "--matching", prefix + ".matching"]
    r = subprocess.run([BIN, mesh, "--on", "faces", "--degree", str(n), "--json"] + files + extra,
                       capture_output=True, text=True, env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
    if not check(r.returncode == 0, "%s: %s" % (name, r.stderr.strip())):
        return
    data = json.loads(r.stdout)
    points, faces = read_obj(prefix + ".obj")
    v = subprocess.run([READER, prefix + ".obj", prefix + ".rosy", prefix + ".sharp"], capture_output=True, text=True)
    if not check(v.returncode == 0, "%s: vcglib reader: %s" % (name, v.stderr.strip())):
        return
    index = {}
    for line in open(prefix + ".sing").read().splitlines()[1:]:
        vertex, k = map(int, line.split())
        index[vertex] = k
    vcg_singular, vcg_sharp = {}, set()
    for line in v.stdout.splitlines():
        t = line.split()
        if t[0] == "sharp":
            vcg_sharp.add((int(t[1]), int(t[2]), int(t[3])))
        else:
            vcg_singular[int(t[0])] = int(t[1])
    ours = {vertex: (-k) % 4 for vertex, k in index.items() if k % 4 != 0}
    # a vertex of index k = 0 mod 4 (k = 4: index 1) turns a whole number of times: no reader that takes the turning
    # modulo 4 can see it; the JSON counts them
    check(data["singular_vertices_multiple_of_n"] == sum(1 for k in index.values() if k % 4 == 0),
          "%s: singular_vertices_multiple_of_n" % name)
    check(vcg_singular == ours, "%s: vcglib finds %d singular vertices, the package %d (%d differ)" %
          (name, len(vcg_singular), len(ours), len(set(vcg_singular.items()) ^ set(ours.items()))))
    angle = None
    if "--feature-angle" in extra:
        angle = float(extra[extra.index("--feature-angle") + 1])
    want = expected_sharp(points, faces, angle)
    got = set()
    for line in open(prefix + ".sharp").read().splitlines()[1:]:
        kind, f, c = map(int, line.split(","))
        got.add((f, c, kind))
    check(got == want, "%s: .sharp holds %d sides, expected %d" % (name, len(got), len(want)))
    check({(min(a, b), max(a, b), k) for a, b, k in vcg_sharp} ==
          {(min(faces[f][c], faces[f][(c + 1) % 3]), max(faces[f][c], faces[f][(c + 1) % 3]), k) for f, c, k in want},
          "%s: the edges vcglib reads from .sharp" % name)
    check_directional_files(name, prefix, points, faces, 4, data)
    print("%-28s %6d faces  %4d singular vertices, vcglib %4d, sharp sides %d" %
          (name, len(faces), len(ours), len(vcg_singular), len(got)))


def hostile_cases():
    """Small and awkward inputs and refused options: a result without NaN, or one line and exit status 1."""
    cases = {
        "triangle": "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        # two tetrahedra: two closed components, each with index sum n chi = 8
        "two_tetrahedra": "OFF\n8 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 0 0\n6 0 0\n5 1 0\n5 0 1\n"
                          "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 4 6 5\n3 4 5 7\n3 4 7 6\n3 5 6 7\n",
        # a sliver of area 1e-13 of its neighbours': the intrinsic mollification
        "sliver": "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1e-13 0\n0.5 1 0\n0.5 -1 0\n3 0 1 2\n3 0 2 3\n3 2 1 3\n",
    }
    for name, text in cases.items():
        mesh = os.path.join(OUT, name + ".off")
        open(mesh, "w").write(text)
        r = subprocess.run([BIN, mesh, "--on", "faces", "--json", "--rosy", os.path.join(OUT, name + ".rosy"),
                            "--rawfield", os.path.join(OUT, name + ".rawfield")], capture_output=True, text=True)
        if not check(r.returncode == 0, "%s: %s" % (name, r.stderr.strip())):
            continue
        data = json.loads(r.stdout)
        numbers = open(os.path.join(OUT, name + ".rawfield")).read().split()
        check("nan" not in " ".join(numbers).lower(), name + ": no NaN in the raw field")
        check(data["index_sum"] + data["boundary_index"] == 4 * data["euler_characteristic"], name + ": Poincare-Hopf")
    mesh = os.path.join(OUT, "triangle.off")
    for extra, words in [(["--on", "faces", "--ply", os.path.join(OUT, "x.ply")], "--ply applies to fields on vertices"),
                         (["--rawfield", os.path.join(OUT, "x.rawfield")], "add --on faces"),
                         (["--on", "edges"], "--on expects vertices or faces"),
                         (["--on", "faces", "--s", "0.5"], "--s must be 0")]:
        r = subprocess.run([BIN, mesh] + extra, capture_output=True, text=True)
        check(r.returncode == 1 and words in r.stderr and r.stderr.count("\n") == 1,
              "%s: refused in one line (%r)" % (" ".join(extra), r.stderr))
        check(not os.path.exists(os.path.join(OUT, "x.ply")) and not os.path.exists(os.path.join(OUT, "x.rawfield")),
              "%s: no output file" % " ".join(extra))


def prescription_case(m):
    """The smoothest field's own singular vertices plus an opposite pair (+1, -1) at the two ends of an edge
    between free interior vertices, prescribed: the field on faces has exactly those, and vcglib reads them."""
    name = m[:-4] + "_prescribed"
    prefix = os.path.join(OUT, name)
    r = subprocess.run([BIN, os.path.join(SHARED, m), "--on", "faces", "--singularities", prefix + ".own",
                        "--mesh-out", prefix + ".own.obj"], capture_output=True, text=True,
                       env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
    if not check(r.returncode == 0, "%s: %s" % (name, r.stderr.strip())):
        return
    asked = dict(tuple(map(int, line.split())) for line in open(prefix + ".own").read().splitlines())
    points, faces = read_obj(prefix + ".own.obj")
    sides = sides_of_edges(faces)
    border = {v for edge, fs in sides.items() if len(fs) == 1 for v in edge}
    pair = next(edge for edge, fs in sorted(sides.items()) if len(fs) == 2 and not (set(edge) & border)
                and not (set(edge) & set(asked)))
    asked[pair[0]], asked[pair[1]] = 1, -1
    with open(prefix + ".asked", "w") as f:
        f.write("".join("%d %d\n" % vk for vk in sorted(asked.items())))
    run_case(name, os.path.join(SHARED, m), ["--prescribe", prefix + ".asked"])
    t = open(prefix + ".sing").read().split()  # n, the count, then vertex k
    got = {int(t[i]): int(t[i + 1]) for i in range(2, len(t), 2)}
    check(got == asked, "%s: the singular vertices are the prescribed ones (%d of %d)" %
          (name, len(set(got.items()) & set(asked.items())), len(asked)))


hostile_cases()
meshes = sorted(f for f in os.listdir(SHARED) if f.endswith(".off"))
for m in meshes:
    run_case(m[:-4], os.path.join(SHARED, m), [])
for m, extra in [("cow", ["--align", "curvature", "--feature-angle", "35"]), ("fandisk", ["--feature-angle", "35"]),
                 ("fertility", ["--align", "curvature"]), ("plane_holes", ["--constrain-boundary", "tangent"])]:
    if m + ".off" in meshes:
        run_case(m + "_" + extra[1].replace("-", "_"), os.path.join(SHARED, m + ".off"), extra)
for m in ["camelhead.off", "cow.off", "fertility.off", "plane_holes.off", "torus_oded.off"]:
    if m in meshes:
        prescription_case(m)
# fewer singularities: vcglib (QuadWild) reads exactly the singular vertices left (bones and plane_holes had
# sides where the parallel field turned so nearly by pi/n that vcglib read other singularities)
for m in ["bones.off", "camelhead.off", "cow.off", "fertility.off", "plane_holes.off", "spot.off",
          "stanford_bunny_open.off"]:
    if m in meshes:
        run_case(m[:-4] + "_cancelled", os.path.join(SHARED, m), ["--cancel-singularities", "0.07"])
check.finish()
