#!/usr/bin/env python3
"""Hostile files, failing outputs and absurd options given to direction_field.

Every file is generated here (nothing is committed). Each run has a memory
limit (1 GiB of address space) and a time limit; every bad case must end with
exit status 1 and exactly one line on stderr, never a signal, a hang or a
partial output file.

    usage: test_hostile_input.py DIRECTION_FIELD OUTPUT_DIR [SHARED_MESH_DIR]
"""
import json
import os
import resource
import shutil
import struct
import subprocess
import sys

from checks import Checks, bumpy_sphere

BIN, OUT = sys.argv[1], sys.argv[2]
SHARED = sys.argv[3] if len(sys.argv) > 3 else ""
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
check = Checks()
MEMORY = 1 << 30


def limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY, MEMORY))


# Under AddressSanitizer (tools/run_sanitizers.sh) no address-space limit can apply.
LIMIT = os.environ.get("SMDF_NO_MEMORY_LIMIT") != "1"


def run(args, timeout=60, memory_limit=True):
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    return subprocess.run([BIN] + args, capture_output=True, text=True, timeout=timeout, env=env,
                          preexec_fn=limit_memory if memory_limit and LIMIT else None)



def expect_error(args, what, contains=None, timeout=60, memory_limit=True):
    try:
        r = run(args, timeout, memory_limit)
    except subprocess.TimeoutExpired:
        check(False, what + ": hangs")
        return None
    lines = r.stderr.splitlines()
    ok = r.returncode == 1 and len(lines) == 1 and lines[0].startswith("direction_field: error: ")
    if contains is not None:
        ok = ok and contains in r.stderr
    check(ok, "%s: status %d, stderr %r" % (what, r.returncode, r.stderr[-300:]))
    return r


def write(name, data):
    path = os.path.join(OUT, name)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())
    return path


# ---------------------------------------------------------------- a valid mesh in every format
OCT_POINTS = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
OCT_FACES = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]


def off_text(points=OCT_POINTS, faces=OCT_FACES, counts=None):
    counts = counts or "%d %d 0" % (len(points), len(faces))
    return "OFF\n%s\n" % counts + "".join("%g %g %g\n" % p for p in points) + \
           "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)


def off_binary(nv=None, nf=None, face_size=None):
    b = b"OFF BINARY\n" + struct.pack(">iii", len(OCT_POINTS) if nv is None else nv,
                                      len(OCT_FACES) if nf is None else nf, 0)
    for p in OCT_POINTS:
        b += struct.pack(">fff", *p)
    for f in OCT_FACES:
        b += struct.pack(">i", 3 if face_size is None else face_size) + struct.pack(">iii", *f) + struct.pack(">i", 0)
    return b


def ply(fmt="binary_little_endian", nv=None, list_size=None, header_extra=""):
    head = "ply\nformat %s 1.0\n%selement vertex %d\nproperty float x\nproperty float y\nproperty float z\n" \
           "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (
               fmt, header_extra, len(OCT_POINTS) if nv is None else nv, len(OCT_FACES))
    if fmt == "ascii":
        body = "".join("%g %g %g\n" % p for p in OCT_POINTS) + "".join(
            "%d %d %d %d\n" % (((3 if list_size is None else list_size),) + f) for f in OCT_FACES)
        return (head + body).encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    body = b"".join(struct.pack(e + "fff", *p) for p in OCT_POINTS)
    for f in OCT_FACES:
        body += struct.pack(e + "B", 3) + struct.pack(e + "iii", *f)
    if list_size is not None:  # a uint list length instead
        head = head.replace("list uchar int", "list uint int")
        body = b"".join(struct.pack(e + "fff", *p) for p in OCT_POINTS)
        for f in OCT_FACES:
            body += struct.pack(e + "I", list_size) + struct.pack(e + "iii", *f)
    return head.encode() + body


def stl_binary(count=None):
    b = b"\0" * 80 + struct.pack("<I", len(OCT_FACES) if count is None else count)
    for f in OCT_FACES:
        b += struct.pack("<fff", 0, 0, 0)
        for v in f:
            b += struct.pack("<fff", *OCT_POINTS[v])
        b += b"\0\0"
    return b


def stl_text():
    s = "solid octahedron\n"
    for f in OCT_FACES:
        s += "facet normal 0 0 0\nouter loop\n" + "".join("vertex %g %g %g\n" % OCT_POINTS[v] for v in f) + \
             "endloop\nendfacet\n"
    return s + "endsolid octahedron\n"


VALID = {"oct.off": off_text(), "oct_bin.off": off_binary(), "oct_bin_le.ply": ply(), "oct_bin_be.ply":
         ply("binary_big_endian"), "oct_ascii.ply": ply("ascii"), "oct_bin.stl": stl_binary(),
         "oct_ascii.stl": stl_text(),
         "oct.obj": "".join("v %g %g %g\n" % p for p in OCT_POINTS) +
                    "".join("f %d/1/1 %d//2 %d\n" % tuple(v + 1 for v in f) for f in OCT_FACES)}
# the same octahedron in odd but valid spellings: byte-order marks, CR-only
# and CRLF line ends, upper-case ASCII STL, a binary STL whose header starts
# with "solid", or with a byte after its last triangle
BOM = "\ufeff"
VALID.update({"bom.obj": BOM + VALID["oct.obj"], "bom.off": BOM + VALID["oct.off"], "bom_ascii.ply": BOM.encode() + ply("ascii"),
              "bom.stl": BOM + stl_text(), "upper.stl": stl_text().upper(), "cr.off": VALID["oct.off"].replace("\n", "\r"),
              "cr.obj": VALID["oct.obj"].replace("\n", "\r"), "crlf.obj": VALID["oct.obj"].replace("\n", "\r\n"),
              "cr.stl": stl_text().replace("\n", "\r"),
              "solid_header.stl": b"solid octahedron" + stl_binary()[16:],
              "solid_header_extra_byte.stl": b"solid octahedron" + stl_binary()[16:] + b"\n"})
for name, data in VALID.items():
    r = run([write(name, data), "--json", "--singularities", os.path.join(OUT, name + ".sing")])
    ok = r.returncode == 0
    if ok:
        d = json.loads(r.stdout)
        ok = d["mesh_vertices"] == 6 and d["mesh_faces"] == 8 and d["index_sum"] == 8 and d["repairs"]["faces_reoriented"] == 0
    check(ok, "valid %s: %s %s" % (name, r.stdout[:200], r.stderr))

# ---------------------------------------------------------------- hostile files
HOSTILE = {
    "plus_minus.obj": "v +-1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    "lowest_index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9223372036854775808\n",
    "float_index.ply": "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face 1\nproperty list uchar float vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                       "3 0 1 1e300\n",
    "float_index_2_64.ply": "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                            "property float z\nelement face 1\nproperty list uchar double vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n3 0 1 18446744073709551616\n",
    "solid_header_short.stl": b"solid octahedron" + stl_binary()[16:-1],
    "property_before_element.ply": b"ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n",
    "huge_faces.off": "OFF\n3 300000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    "huge_vertices.off": "OFF\n2000000000 1 0\n0 0 0\n",
    "overflowing_count.off": "OFF\n99999999999999999999 1 0\n0 0 0\n",
    "negative_count.off": "OFF\n-5 1 0\n0 0 0\n",
    "huge_face_size.off": "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n999999999 0 1 2\n",
    "bin_huge_vertices.off": off_binary(nv=2000000000),
    "bin_negative_faces.off": off_binary(nf=-3),
    "bin_huge_face_size.off": off_binary(face_size=1000000000),
    "huge_vertex_count.ply": ply(nv=2000000000),
    "huge_vertex_count_ascii.ply": ply("ascii", nv=2000000000),
    "negative_count.ply": ply("ascii", nv=-1),
    "huge_list.ply": ply(list_size=2000000000),
    "huge_list_ascii.ply": ply("ascii", list_size=2000000000),
    "no_end_header.ply": b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n",
    "unknown_type.ply": b"ply\nformat ascii 1.0\nelement vertex 1\nproperty quaternion x\nend_header\n1\n",
    "huge_count.stl": stl_binary(count=4000000000)[:84 + 50 * 8] + b"x",
    "not_a_solid.stl": "solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0\n",
    "zero_index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
    "far_index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999\n",
    "huge_index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999999\n",
    "nan.obj": "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    "inf.off": "OFF\n3 1 0\n1e999 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    "empty.off": "",
    "empty.ply": "",
    "empty.stl": "",
    "empty.obj": "",
    "no_faces.off": "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n",
    "text.off": "hello world\n",
    "unknown.xyz": "0 0 0\n",
}
for name, data in HOSTILE.items():
    expect_error([write(name, data)], "hostile file " + name)

# a huge non-planar polygon (CGAL's exhaustive triangulation would take hours): a fan, in seconds
import random as _random
_rng = _random.Random(7)
_n = 20000
big = write("huge_polygon.off", "OFF\n%d 1 0\n" % _n + "".join("%r %r %r\n" % (_rng.random(), _rng.random(), _rng.random())
                                                               for _ in range(_n)) + "%d %s\n" % (_n, " ".join(map(str, range(_n)))))
try:
    r = run([big, "--json"], timeout=120)
    check(r.returncode == 0 and json.loads(r.stdout)["repairs"]["polygons_triangulated"] == 1,
          "huge polygon: %d %r" % (r.returncode, r.stderr))
except subprocess.TimeoutExpired:
    check(False, "huge polygon: hangs")

# many non-planar polygons of 256 vertices: CGAL's search for a few of them, fans for the rest
many = write("many_polygons.off", "OFF\n%d 300 0\n" % (256 * 300) +
             "".join("%r %r %r\n" % (_rng.random(), _rng.random(), _rng.random()) for _ in range(256 * 300)) +
             "".join("256 %s\n" % " ".join(map(str, range(256 * j, 256 * j + 256))) for j in range(300)))
try:
    r = run([many, "--json"], timeout=60)
    check(r.returncode == 0, "many polygons: %d %r" % (r.returncode, r.stderr))
except subprocess.TimeoutExpired:
    check(False, "many polygons: too slow")

# a run stopped by a signal leaves no file of its own (the slow file above keeps it busy)
import signal as _signal
import time as _time
stopped = os.path.join(OUT, "stopped")
os.makedirs(stopped)
for sig in [_signal.SIGINT, _signal.SIGTERM]:
    p = subprocess.Popen([BIN, many, "--directions", os.path.join(stopped, "d.txt"), "--vtk", os.path.join(stopped, "f.vtk")],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _time.sleep(1.0)
    p.send_signal(sig)
    p.wait(timeout=30)
    check(p.returncode == -sig and os.listdir(stopped) == [],
          "stopped by signal %d: status %d, left %s" % (sig, p.returncode, os.listdir(stopped)))

# truncated binary files: every cut is an error or a smaller mesh, never a signal
for name in ["oct_bin.off", "oct_bin_le.ply", "oct_bin_be.ply", "oct_bin.stl"]:
    data = VALID[name] if isinstance(VALID[name], bytes) else VALID[name].encode()
    for cut in range(1, len(data), max(1, len(data) // 23)):
        r = run([write("cut_" + name, data[:cut]), "--json"])
        check(r.returncode in (0, 1) and (r.returncode == 0 or len(r.stderr.splitlines()) == 1),
              "truncated %s at %d: status %d %r" % (name, cut, r.returncode, r.stderr))

# a word of a megabyte and terminal escape codes: quoted short and printable
for ext, text in [("off", "OFF\n3 1 0\n" + "x" * 1000000 + " 0 0\n0 1 0\n0 0 1\n3 0 1 2\n"),
                  ("obj", "v " + "y" * 1000000 + " 0 0\n"), ("off", "\033[2J\033[31mEVIL\n")]:
    r = expect_error([write("quoted." + ext, text)], "a long or escaping word in ." + ext)
    check(r is not None and len(r.stderr) < 300 and "\033" not in r.stderr,
          "." + ext + ": the message quotes at most a few dozen printable characters")
# a device (no end) is refused at once
zero = os.path.join(OUT, "zero.off")
if not os.path.lexists(zero):
    os.symlink("/dev/zero", zero)
expect_error([zero], "a link to /dev/zero", "device", timeout=20)
# a sparse file of 3 GB (a valid octahedron, then zeros) is read at its size:
# under the 1 GiB limit an out-of-memory line, never a crash
if LIMIT:
    sparse = write("sparse.off", off_text())
    os.truncate(sparse, 3 << 30)
    expect_error([sparse], "a sparse file of 3 GB", "out of memory", timeout=30)
    os.remove(sparse)

# a directory, a missing file
expect_error([OUT], "a directory as the mesh", "directory")
expect_error([os.path.join(OUT, "missing.off")], "a missing mesh", "cannot open")

# ---------------------------------------------------------------- outputs
mesh = os.path.join(OUT, "oct.off")
OUTPUT_OPTIONS = ["--directions", "--singularities", "--json-file", "--png", "--vtk", "--ply", "--rosy", "--ffield",
                  "--singularity-list", "--streamlines", "--mesh-out"]
for option in OUTPUT_OPTIONS:
    r = expect_error([mesh, option, "/dev/full"], option + " /dev/full", "/dev/full")
    check(r is not None and r.stdout == "", option + " /dev/full: nothing on stdout")
    expect_error([mesh, option, os.path.join(OUT, "no_such_folder", "x")], option + " in a missing folder")
    expect_error([mesh, option, OUT], option + " naming a folder", "directory")
# stdout on a full device
with open("/dev/full", "w") as full:
    r = subprocess.run([BIN, mesh, "--json"], stdout=full, stderr=subprocess.PIPE, text=True, timeout=60)
check(r.returncode == 1 and "standard output" in r.stderr, "stdout on /dev/full: %d %r" % (r.returncode, r.stderr))

# an unwritable output fails before the mesh is read: the mesh is a pipe nobody writes
fifo = os.path.join(OUT, "never_written.off")
os.mkfifo(fifo)
expect_error([fifo, "--directions", os.path.join(OUT, "no_such_folder", "d.txt")], "unwritable output before reading",
             timeout=20)

# a failure after other outputs were written leaves none of them, and no temporary file
kept = os.path.join(OUT, "kept")
os.makedirs(kept)
expect_error([mesh, "--directions", os.path.join(kept, "d.txt"), "--vtk", os.path.join(kept, "f.vtk"),
              "--json-file", "/dev/full"], "late failure")
check(os.listdir(kept) == [], "late failure leaves no file: %s" % os.listdir(kept))
# an existing output is kept as it was when the run fails
with open(os.path.join(kept, "d.txt"), "w") as f:
    f.write("old\n")
expect_error([mesh, "--directions", os.path.join(kept, "d.txt"), "--png", "/dev/full"], "late failure, old file")
check(open(os.path.join(kept, "d.txt")).read() == "old\n" and os.listdir(kept) == ["d.txt"], "old output kept")
# the input is never an output
before = open(mesh).read()
expect_error([mesh, "--directions", mesh], "output over the input", "input mesh")
check(open(mesh).read() == before, "input unchanged")
expect_error([mesh, "--directions", os.path.join(OUT, "same"), "--vtk", os.path.join(OUT, "same")], "one file twice")
# success: every file there, nothing else
good = os.path.join(OUT, "good")
os.makedirs(good)
r = run([mesh, "--directions", os.path.join(good, "d.txt"), "--vtk", os.path.join(good, "f.vtu"),
         "--json-file", os.path.join(good, "r.json"), "--quiet"])
check(r.returncode == 0 and r.stderr == "" and sorted(os.listdir(good)) == ["d.txt", "f.vtu", "r.json"],
      "success writes exactly the outputs: %s %r" % (sorted(os.listdir(good)), r.stderr))

# ---------------------------------------------------------------- options
for args, what in [(["--degree", "0"], "degree 0"), (["--degree", "1001"], "degree above the maximum"),
                   (["--degree", "2147483647"], "degree 2^31-1"), (["--degree", "4.5"], "degree not an integer"),
                   (["--seed", "-1"], "negative seed"), (["--max-iterations", "-1"], "negative iterations"),
                   (["--max-iterations", "4294967296"], "iterations above 2^32-1"), ([""], "empty mesh name"),
                   (["--lambda", "1"], "lambda without guidance"), (["--alignment-weight", "0.5"], "weight alone"),
                   (["--s", "2"], "s out of range"), (["--s", "nan"], "s NaN"), (["--tolerance", "-1"], "tolerance < 0"),
                   (["--feature-angle", "200"], "feature angle"), (["--align", "curvature", "--alignment-weight", "1"],
                                                                   "weight 1"),
                   (["--rosy", os.path.join(OUT, "r.rosy"), "--degree", "6"], "rosy with n = 6"),
                   (["--ffield", os.path.join(OUT, "r.ffield"), "--degree", "2"], "ffield with n = 2"),
                   (["--directions"], "option without value"), (["--bogus"], "unknown option"),
                   ([mesh, mesh], "two meshes")]:
    r = expect_error([mesh] + args if args and args[0] not in ("", mesh) else args, "option: " + what)
    if r is not None and what == "feature angle":
        check("200" in r.stderr and "200.000000" not in r.stderr, "numbers printed compactly: %r" % r.stderr)

# --max-iterations 0: not converged, its real residual, said on stderr, exit 0
r = run([mesh, "--max-iterations", "0", "--json"])
d = json.loads(r.stdout) if r.returncode == 0 else {}
check(r.returncode == 0 and d.get("converged") is False and (d.get("residual") or 0) > 0 and "warning" in r.stderr,
      "--max-iterations 0: %s %r" % (r.stdout[:300], r.stderr))

# guidance vectors of any size: scaled safely (the same field for any uniform scale)
guidance = [(0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1), (1, 0, 0), (1, 0, 0)]
results = []
for scale in [1.0, 1e200, 1e-200]:
    g = write("guidance_%g.txt" % scale, "".join("%r %r %r\n" % tuple(scale * x for x in v) for v in guidance))
    r = run([mesh, "--guidance", g, "--directions", os.path.join(OUT, "g%g.txt" % scale), "--json"])
    ok = r.returncode == 0 and json.loads(r.stdout)["alignment_weight"] > 0
    check(ok, "guidance scaled by %g: %s %r" % (scale, r.stdout[:200], r.stderr))
    # a direct solve: converged, no warning about an eigen-solve that did not run
    check(ok and json.loads(r.stdout)["converged"] is True and "warning" not in r.stderr,
          "guidance scaled by %g: converged, no warning: %r" % (scale, r.stderr))
    results.append([[float(x) for x in l.split()] for l in open(os.path.join(OUT, "g%g.txt" % scale))] if ok else None)
# the same cross field (n = 4): at each vertex the directions differ by a multiple of 90 degrees in the
# tangent plane, cos(4 theta) = 8 c^4 - 8 c^2 + 1 = 1 for c = cos(theta) (which of the four directions
# represents the cross may change where the rounding of the coefficient's angle crosses the branch cut)
def same_cross(u, v):
    c = sum(a * b for a, b in zip(u, v))
    return 8 * c ** 4 - 8 * c ** 2 + 1 > 1 - 1e-9
check(None not in results and all(same_cross(u, v) for r in results[1:] for u, v in zip(results[0], r)),
      "guidance: the same field at every scale")
# an extreme alignment weight is computed, not refused
r = run([mesh, "--align", "curvature", "--alignment-weight", "1e-300", "--json"])
check(r.returncode == 0, "--alignment-weight 1e-300: %d %r" % (r.returncode, r.stderr))

# ---------------------------------------------------------------- outputs, third round
import signal as _signal
import time as _time
def leftovers(folder):
    return [n for n in os.listdir(folder) if ".partial-" in n]

work = os.path.join(OUT, "same_file")
os.makedirs(work, exist_ok=True)
for a, b in [("a.txt", "./a.txt"), ("a.txt", ".//a.txt"), ("a.txt", os.path.join(work, "a.txt")),
             ("a.txt", "../same_file/a.txt")]:
    r = subprocess.run([BIN, mesh, "--directions", a, "--singularity-list", b], cwd=work, capture_output=True,
                       text=True, timeout=60)
    check(r.returncode == 1 and "both write" in r.stderr and r.stderr.count("\n") == 1,
          "one file through two spellings (%s, %s): %r" % (a, b, r.stderr))
write("same_file/target.txt", "old\n")
os.symlink("target.txt", os.path.join(work, "link.txt"))
r = subprocess.run([BIN, mesh, "--directions", "target.txt", "--singularity-list", "link.txt"], cwd=work,
                   capture_output=True, text=True, timeout=60)
check(r.returncode == 1 and "both write" in r.stderr, "one file through a link: %r" % r.stderr)

# signals whose default action ends the program: no partial file left (the mesh is a pipe not yet written)
for sig in ["SIGQUIT", "SIGUSR1", "SIGUSR2", "SIGALRM", "SIGXCPU", "SIGVTALRM", "SIGXFSZ", "SIGTERM"]:
    folder = os.path.join(OUT, "signal_" + sig)
    os.makedirs(folder, exist_ok=True)
    pipe = os.path.join(folder, "mesh.off")
    os.mkfifo(pipe)
    p = subprocess.Popen([BIN, pipe, "--directions", os.path.join(folder, "d.txt")], stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL)
    for _ in range(100):  # until the output's temporary file exists
        if leftovers(folder): break
        _time.sleep(0.05)
    p.send_signal(getattr(_signal, sig))
    p.wait(timeout=20)
    check(p.returncode != 0 and not leftovers(folder) and not os.path.exists(os.path.join(folder, "d.txt")),
          "%s: ended (%d), no partial file (%s)" % (sig, p.returncode, leftovers(folder)))

# standard output closed early (| true): an error, no file, no partial file
folder = os.path.join(OUT, "closed_stdout")
os.makedirs(folder, exist_ok=True)
reader, writer = os.pipe()
os.close(reader)
r = subprocess.run([BIN, mesh, "--json", "--directions", os.path.join(folder, "d.txt")], stdout=writer,
                   stderr=subprocess.PIPE, text=True, timeout=60)
os.close(writer)
check(r.returncode == 1 and "standard output" in r.stderr and not leftovers(folder) and
      not os.path.exists(os.path.join(folder, "d.txt")), "a closed standard output: %d %r" % (r.returncode, r.stderr))

# a rename that fails at the end (an output's name became a folder while the mesh was read): the outputs
# already renamed are taken back, and the older files of their names are restored
folder = os.path.join(OUT, "failing_commit")
os.makedirs(folder, exist_ok=True)
write("failing_commit/d.txt", "older directions\n")
pipe = os.path.join(folder, "mesh.off")
os.mkfifo(pipe)
p = subprocess.Popen([BIN, pipe, "--directions", os.path.join(folder, "d.txt"), "--singularity-list",
                      os.path.join(folder, "s.txt")], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
for _ in range(100):
    if len(leftovers(folder)) == 2: break
    _time.sleep(0.05)
os.makedirs(os.path.join(folder, "s.txt", "in_the_way"))
with open(pipe, "w") as f:
    f.write(off_text())
err = p.communicate(timeout=60)[1]
check(p.returncode == 1 and open(os.path.join(folder, "d.txt")).read() == "older directions\n" and
      not leftovers(folder) and not [n for n in os.listdir(folder) if n.endswith(".older")],
      "a failing rename restores the older file: %d %r %s" % (p.returncode, err, os.listdir(folder)))

# a vertex of valence 100,000 (a flat fan, and a closed double cone): the
# repair and the assembly are linear in the valence (their time is measured
# in benchmark/; here the 60 s limit of run() guards against a quadratic
# return), and the result is right
import math as _math
valence = 100000
ring = ["%r %r 0\n" % (_math.cos(2 * _math.pi * i / valence), _math.sin(2 * _math.pi * i / valence)) for i in range(valence)]
write("fan.off", "OFF\n%d %d 0\n" % (valence + 1, valence) + "".join(ring) + "0 0 1\n" +
      "".join("3 %d %d %d\n" % (valence, i, (i + 1) % valence) for i in range(valence)))
write("double_cone.off", "OFF\n%d %d 0\n" % (valence + 2, 2 * valence) + "".join(ring) + "0 0 1\n0 0 -1\n" +
      "".join("3 %d %d %d\n" % (valence, i, (i + 1) % valence) for i in range(valence)) +
      "".join("3 %d %d %d\n" % (valence + 1, (i + 1) % valence, i) for i in range(valence)))
for name, faces, index_sum in (("fan.off", valence, None), ("double_cone.off", 2 * valence, 8)):
    r = run([os.path.join(OUT, name), "--json"])
    d = json.loads(r.stdout) if r.returncode == 0 else None
    check(d is not None and d["mesh_faces"] == faces and sum(d["repairs"].values()) == 0 and
          (index_sum is None or d["index_sum"] == index_sum),
          "valence %d, %s: status %d %r" % (valence, name, r.returncode, r.stderr[-200:]))

# a shared mesh at any scale: coordinates times 1e-300 ... 1e300 give the
# unscaled mesh's singular faces with the same indices
spot = os.path.join(SHARED, "spot.off")
if os.path.isfile(spot):
    lines = open(spot).read().split("\n")
    nv = int(lines[1].split()[0])
    singular = {}
    for factor in [1.0, 1e-300, 1e-200, 1e-80, 1e80, 1e200, 1e300]:
        scaled = lines[:2] + [" ".join(repr(float(x) * factor) for x in line.split()) for line in lines[2:2 + nv]] + \
                 lines[2 + nv:]
        name = write("spot_%g.off" % factor, "\n".join(scaled))
        listing = os.path.join(OUT, "spot_%g.sing" % factor)
        r = run([name, "--singularity-list", listing, "--quiet"])
        singular[factor] = [l.split()[:3] for l in open(listing) if not l.startswith("#")] if r.returncode == 0 \
            else "status %d %r" % (r.returncode, r.stderr)
    for factor, faces in singular.items():
        check(faces == singular[1.0] and len(faces) > 2, "spot scaled by %g: the same singular faces" % factor)
else:
    check.skip("the scale sweep: no shared meshes")

# every output finite at every scale, field lines and markers included, and
# the same field lines: a bumpy sphere (512 faces, a unique smoothest field)
# times 1e-299 ... 1e299 (near 1e±80 the squares of the normals' cross
# products leave double's range)
sphere_points, sphere_faces = bumpy_sphere()
line_points = {}
for factor in [1.0, 1e-299, 1e-100, 1e-80, 1e80, 1e100, 1e299]:
    name = write("sphere_%g.off" % factor, "OFF\n%d %d 0\n" % (len(sphere_points), len(sphere_faces)) +
                 "".join("%r %r %r\n" % tuple(factor * x for x in p) for p in sphere_points) +
                 "".join("3 %d %d %d\n" % f for f in sphere_faces))
    outputs = {o: os.path.join(OUT, "sphere_%g_%s" % (factor, ending)) for o, ending in
               [("--vtk", "field.vtk"), ("--ply", "field.ply"), ("--streamlines", "lines.vtu"),
                ("--vtk-singularities", "markers.vtu"), ("--directions", "directions.txt")]}
    r = run([name, "--quiet"] + [x for o, path in outputs.items() for x in (o, path)])
    texts = {o: open(path).read().lower() if r.returncode == 0 else "" for o, path in outputs.items()}
    check(r.returncode == 0 and not any("nan" in t or "inf" in t for t in texts.values()),
          "sphere scaled by %g: every output finite (%d %r)" % (factor, r.returncode, r.stderr[-200:]))
    count = texts["--streamlines"].split('numberofpoints="')[1].split('"')[0] if r.returncode == 0 else "0"
    line_points[factor] = int(count)
check(all(line_points[f] == line_points[1.0] > 0 for f in line_points),
      "the same field lines at every power-of-ten scale of a sphere: %r" % line_points)

# no output may replace an input, whatever its spelling: the prescription
# and the guidance compared by device and inode, through links too
work = os.path.join(OUT, "inputs_as_outputs")
os.makedirs(work, exist_ok=True)
sphere_mesh = os.path.join(OUT, "sphere_1.off")
r = run([sphere_mesh, "--degree", "4", "--singularities", os.path.join(work, "p.sing"), "--quiet"])
guidance_text = "".join("1 0 0\n" for _ in sphere_points)
write("inputs_as_outputs/g.txt", guidance_text)
os.symlink("p.sing", os.path.join(work, "link.sing"))
prescription = open(os.path.join(work, "p.sing")).read()
for args, what in [(["--prescribe", "p.sing", "--vtk", "./p.sing"], "--prescribe"),
                   (["--prescribe", "p.sing", "--directions", "link.sing"], "--prescribe"),
                   (["--guidance", "g.txt", "--align", "curvature", "--png", "./g.txt"], "--guidance"),
                   (["--guidance", "g.txt", "--png", os.path.join(work, "g.txt")], "--guidance")]:
    r = subprocess.run([BIN, sphere_mesh, "--quiet"] + args, cwd=work, capture_output=True, text=True, timeout=60)
    check(r.returncode == 1 and what in r.stderr and "never overwritten" in r.stderr,
          "%s: refused (%d %r)" % (" ".join(args), r.returncode, r.stderr))
check(open(os.path.join(work, "p.sing")).read() == prescription and
      open(os.path.join(work, "g.txt")).read() == guidance_text and os.path.islink(os.path.join(work, "link.sing")),
      "the inputs are untouched")
# a folder or a device as a prescription or guidance: one line
for option in ["--prescribe", "--guidance"]:
    expect_error([sphere_mesh, option, work], option + " given a folder", "is a directory")
    expect_error([sphere_mesh, option, "/dev/zero"], option + " given a device", "is a device")
# a prescription with a UTF-8 byte order mark is read as without it
bom = write("inputs_as_outputs/bom.sing", b"\xef\xbb\xbf" + prescription.encode())
r = run([sphere_mesh, "--prescribe", bom, "--quiet"])
check(r.returncode == 0, "a prescription with a byte order mark: %d %r" % (r.returncode, r.stderr))
# an output that is a link is written through it: the link stays
write("inputs_as_outputs/target.txt", "old\n")
os.symlink("target.txt", os.path.join(work, "out.txt"))
r = subprocess.run([BIN, sphere_mesh, "--quiet", "--directions", "out.txt"], cwd=work, capture_output=True,
                   text=True, timeout=60)
check(r.returncode == 0 and os.path.islink(os.path.join(work, "out.txt")) and
      len(open(os.path.join(work, "target.txt")).read().splitlines()) == len(sphere_points),
      "an output link is written through: %d %r" % (r.returncode, r.stderr))

check.finish()
