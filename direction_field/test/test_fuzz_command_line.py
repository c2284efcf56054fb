#!/usr/bin/env python3
"""Fuzz-style test of the reader and the solver, through the command line:
randomly perturbed and truncated OFF files, and the same mesh as binary and
ASCII PLY, binary STL, binary OFF and OBJ with random bytes changed, inserted,
deleted or cut, must give either a result (exit 0,
finite unit or zero directions, one JSON line) or a clean error (exit 1, one
line on stderr) -- never a crash, a hang or a NaN.

usage: test_fuzz_command_line.py DIRECTION_FIELD SHARED_MESH_DIR OUTPUT_DIR [CASES]
"""
import json, math, os, random, subprocess, sys

binary, shared, out = sys.argv[1], sys.argv[2], sys.argv[3]
cases = int(sys.argv[4]) if len(sys.argv) > 4 else 300
os.makedirs(out, exist_ok=True)
rng = random.Random(20261122)

base_path = os.path.join(shared, "sphere_oded.off") if shared else ""
if base_path and os.path.exists(base_path):
    base = open(base_path).read()
else:  # an octahedron
    base = "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n" \
           "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n"

garbage = ["nan", "-nan", "inf", "-inf", "-1", "1e308", "-1e308", "1e-320", "999999999", "abc", "", "0.5", "3",
           "4", "0", "2147483648", "-0", "1e3", "#", "\x00", "3 1 1 1"]

def mutate(text):
    lines = text.split("\n")
    kind = rng.randrange(9)
    if kind == 0:  # truncate anywhere
        return text[:rng.randrange(len(text))], "truncated"
    if kind in (1, 2, 3):  # replace tokens
        for _ in range(rng.randrange(1, 4)):
            i = rng.randrange(len(lines))
            tokens = lines[i].split()
            if tokens:
                tokens[rng.randrange(len(tokens))] = rng.choice(garbage)
                lines[i] = " ".join(tokens)
        return "\n".join(lines), "token"
    if kind == 4:  # delete lines
        for _ in range(rng.randrange(1, 5)):
            del lines[rng.randrange(len(lines))]
        return "\n".join(lines), "delete"
    if kind == 5:  # duplicate lines
        for _ in range(rng.randrange(1, 5)):
            i = rng.randrange(len(lines))
            lines.insert(i, lines[i])
        return "\n".join(lines), "duplicate"
    if kind == 6:  # header counts
        tokens = lines[1].split()
        tokens[rng.randrange(len(tokens))] = str(rng.choice([0, 1, 3, 7, 10**6, -5]))
        lines[1] = " ".join(tokens)
        return "\n".join(lines), "header"
    if kind == 7:  # perturb coordinates: degenerate, coincident, huge, tiny
        nv = int(text.split("\n")[1].split()[0])
        for _ in range(rng.randrange(1, 20)):
            i = 2 + rng.randrange(nv)
            j = 2 + rng.randrange(nv)
            lines[i] = rng.choice([lines[j], "0 0 0", "1e-300 1e-300 1e-300", "1e150 0 0",
                                   " ".join(str(float(x) * (1 + 1e-14)) for x in lines[i].split()[:3])])
        return "\n".join(lines), "coordinates"
    # random bytes
    pos = rng.randrange(len(text))
    junk = "".join(chr(rng.randrange(1, 256)) for _ in range(rng.randrange(1, 10)))
    return text[:pos] + junk + text[pos:], "bytes"

# The same mesh in the other formats the reader knows, mutated byte-wise:
# flips, insertions, deletions and truncations anywhere, headers included.
import struct


def other_formats(text):
    tokens = [l.split("#")[0] for l in text.split("\n")]
    words = " ".join(tokens).split()
    nv, nf = int(words[1]), int(words[2])
    pts = [tuple(float(x) for x in words[4 + 3 * i:7 + 3 * i]) for i in range(nv)]
    at, faces = 4 + 3 * nv, []
    for _ in range(nf):
        k = int(words[at])
        faces.append(tuple(int(x) for x in words[at + 1:at + 1 + k]))
        at += 1 + k
    ply_head = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                "element face %d\nproperty list uchar int vertex_indices\nend_header\n")
    binary_ply = (ply_head % ("binary_little_endian", nv, nf)).encode() + \
        b"".join(struct.pack("<fff", *p) for p in pts) + \
        b"".join(struct.pack("<B", len(f)) + struct.pack("<%di" % len(f), *f) for f in faces)
    ascii_ply = (ply_head % ("ascii", nv, nf) + "".join("%r %r %r\n" % p for p in pts) +
                 "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)).encode()
    stl = b"\0" * 80 + struct.pack("<I", nf) + b"".join(
        struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *pts[v]) for v in f[:3]) + b"\0\0" for f in faces)
    binary_off = b"OFF BINARY\n" + struct.pack(">3i", nv, nf, 0) + b"".join(struct.pack(">3f", *p) for p in pts) + \
        b"".join(struct.pack(">i", len(f)) + struct.pack(">%di" % len(f), *f) + struct.pack(">i", 0) for f in faces)
    obj = ("".join("v %r %r %r\n" % p for p in pts) +
           "".join("f %s\n" % " ".join(str(v + 1) for v in f) for f in faces)).encode()
    return [("ply", binary_ply), ("ply", ascii_ply), ("stl", stl), ("off", binary_off), ("obj", obj)]


def mutate_bytes(data):
    data = bytearray(data)
    kind = rng.randrange(4)
    if kind == 0:
        return bytes(data[:rng.randrange(len(data))])
    for _ in range(rng.randrange(1, 6)):
        pos = rng.randrange(len(data))
        if kind == 1:
            data[pos] = rng.randrange(256)
        elif kind == 2:
            data[pos:pos] = bytes(rng.randrange(256) for _ in range(rng.randrange(1, 5)))
        else:
            del data[pos:pos + rng.randrange(1, 5)]
    return bytes(data)


failures = 0
outcomes = {"ok": 0, "error": 0}
byte_cases = [(ext, data) for ext, data in other_formats(base) for _ in range(40)]
for case in range(cases + len(byte_cases)):
    if case < cases:
        text, kind = mutate(base)
        path = os.path.join(out, "case.off")
        with open(path, "w", encoding="latin-1") as f:
            f.write(text)
    else:
        ext, data = byte_cases[case - cases]
        kind = "bytes of ." + ext
        text = mutate_bytes(data).decode("latin-1")
        path = os.path.join(out, "case." + ext)
        with open(path, "w", encoding="latin-1") as f:
            f.write(text)
    dirs = os.path.join(out, "dirs.txt")
    if os.path.exists(dirs):
        os.remove(dirs)
    import time
    t0 = time.time()
    try:
        p = subprocess.run([binary, path, "--degree", str(rng.choice([1, 2, 4])), "--json", "--directions", dirs,
                            "--max-iterations", "300"], capture_output=True, timeout=60)
    except subprocess.TimeoutExpired:
        failures += 1
        print(f"FAILED case {case} ({kind}): hang")
        continue
    if time.time() - t0 > 1.0:
        print(f"slow case {case} ({kind}): {time.time() - t0:.1f} s, status {p.returncode}")
        with open(os.path.join(out, f"slow_{case}.off"), "w", encoding="latin-1") as f:
            f.write(text)
    problem = None
    if p.returncode == 0:
        outcomes["ok"] += 1
        try:
            d = json.loads(p.stdout.decode())
            for line in open(dirs):
                v = [float(x) for x in line.split()]
                length = math.sqrt(sum(x * x for x in v))
                if not all(math.isfinite(x) for x in v) or not (abs(length - 1) < 1e-9 or length == 0):
                    problem = f"bad direction {line.strip()}"
                    break
            if not all(math.isfinite(e) for e in d["eigenvalues"]):
                problem = "non-finite eigenvalue"
        except Exception as e:  # noqa
            problem = f"unreadable output: {e}"
    elif p.returncode == 1:
        outcomes["error"] += 1
        if p.stderr.decode(errors="replace").count("\n") != 1 or p.stdout:
            problem = f"error output is not one line on stderr: {p.stderr!r}"
    else:
        problem = f"exit status {p.returncode} (crash?) {p.stderr[-300:]!r}"
    if problem:
        failures += 1
        with open(os.path.join(out, f"failed_{case}" + os.path.splitext(path)[1]), "w", encoding="latin-1") as f:
            f.write(text)
        print(f"FAILED case {case} ({kind}): {problem}")

print(f"fuzz: {outcomes['ok']} results, {outcomes['error']} clean errors")
print(f"{cases + len(byte_cases) - failures} passed, {failures} failed")
sys.exit(1 if failures else 0)
