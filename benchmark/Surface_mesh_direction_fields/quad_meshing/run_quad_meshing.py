#!/usr/bin/env python3
"""Quad meshes from the package's field against QuadWild's own field, through
the same QuadWild (the Bi-MDF fork, built by build_quadwild.sh).

For each mesh and each feature setting (none, or --feature-angle A):
- package: `direction_field MESH --on faces --mesh-out M.obj --rosy M.rosy
  --sharp M.sharp [--feature-angle A]`, then `quadwild M.obj 2 CONFIG M.rosy
  M.sharp` and `quad_from_patches M_rem_p0.obj 0 FLOW stats.json`;
- QuadWild's own: the same M.obj through `quadwild M.obj 2 CONFIG` (its
  remeshing, features at A degrees or none, and field) and quad_from_patches.
  With --on-remeshed the package's field is computed on QuadWild's remeshed
  mesh instead of MESH, so that both fields are on one mesh.
Reported per run: quads, irregular vertices of the quad mesh (interior
valence != 4, boundary valence not 1 or 2: quad_tools/quadstats.py's rule),
the share of the feature lines' length that lies on edges of the quad mesh,
and the seconds of each step. Needs numpy and scipy (Debian's python3).

    run_quad_meshing.py --quadwild OUT --program BUILD/bin/direction_field
                        [--feature-angles none,35] [--field-options OPTIONS] [--timeout S] [--json FILE] MESH...
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.spatial import cKDTree


def read_obj(path):
    points, faces = [], []
    with open(path) as f:
        for line in f:
            s = line.split()
            if not s:
                continue
            if s[0] == "v":
                points.append([float(x) for x in s[1:4]])
            elif s[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in s[1:]])
    return np.array(points), faces


def quad_statistics(path):
    """quads, faces, irregular vertices (quadstats.py's rule)."""
    points, faces = read_obj(path)
    valence = np.zeros(len(points), dtype=int)
    edge_count = {}
    for f in faces:
        for j, a in enumerate(f):
            b = f[(j + 1) % len(f)]
            valence[a] += 1
            key = (min(a, b), max(a, b))
            edge_count[key] = edge_count.get(key, 0) + 1
    boundary = set()
    for (a, b), c in edge_count.items():
        if c == 1:
            boundary.update((a, b))
    used = set(v for f in faces for v in f)
    irregular = sum(1 for v in used if (v not in boundary and valence[v] != 4) or
                    (v in boundary and valence[v] not in (1, 2)))
    return {"faces": len(faces), "quads": sum(1 for f in faces if len(f) == 4), "irregular": irregular}


def sharp_segments(mesh_obj, sharp_path):
    """The feature edges of a .sharp file ('type,face,edge' per line) as segments."""
    points, faces = read_obj(mesh_obj)
    segments = set()
    with open(sharp_path) as f:
        count = int(f.readline())
        for _ in range(count):
            _, face, side = (int(x) for x in f.readline().split(","))
            a, b = faces[face][side], faces[face][(side + 1) % 3]
            segments.add((min(a, b), max(a, b)))
    return [(points[a], points[b]) for a, b in segments]


def features_kept(segments, quad_obj, tolerance):
    """The share of the segments' length whose sample points lie within
    `tolerance` of an edge of the quad mesh (edges sampled densely)."""
    if not segments:
        return None
    points, faces = read_obj(quad_obj)
    samples = []
    step = tolerance
    for f in faces:
        for j, a in enumerate(f):
            b = f[(j + 1) % len(f)]
            if a < b or len(f) < 3:
                length = np.linalg.norm(points[b] - points[a])
                count = max(2, int(length / step) + 1)
                t = np.linspace(0., 1., count)[:, None]
                samples.append(points[a] + t * (points[b] - points[a]))
    tree = cKDTree(np.vstack(samples))
    kept = total = 0.
    for p, q in segments:
        length = np.linalg.norm(q - p)
        t = np.linspace(0.1, 0.9, 5)[:, None]
        distance, _ = tree.query(p + t * (q - p))
        kept += length * np.mean(distance < 2. * tolerance)
        total += length
    return kept / total if total > 0 else None


def run(command, cwd, timeout, log):
    start = time.monotonic()
    with open(log, "a") as out:
        out.write("$ " + " ".join(command) + "\n")
        out.flush()
        result = subprocess.run(command, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, timeout=timeout)
    return result.returncode, time.monotonic() - start


def quadwild_steps(args, work, mesh_obj, extra, config):
    """quadwild (steps 1-2) and quad_from_patches; returns statistics and times."""
    log = os.path.join(work, "log.txt")
    source = os.path.join(args.quadwild, "src")
    base = mesh_obj[:-4]
    record = {}
    try:
        code, record["quadwild_s"] = run([os.path.join(args.quadwild, "bin", "quadwild"), mesh_obj, "2", config] + extra,
                                         source, args.timeout, log)
        if code != 0:
            return dict(record, failed="quadwild exit %d" % code)
        code, record["quad_from_patches_s"] = run(
            [os.path.join(args.quadwild, "bin", "quad_from_patches"), base + "_rem_p0.obj", "0",
             "config/main_config/flow_noalign_lemon.txt", os.path.join(work, "stats.json")], source, args.timeout, log)
    except subprocess.TimeoutExpired:
        return dict(record, failed="timeout")
    quad = base + "_rem_p0_0_quadrangulation_smooth.obj"
    if code != 0 or not os.path.exists(quad):
        return dict(record, failed="quad_from_patches exit %d" % code)
    record.update(quad_statistics(quad))
    record["quad_mesh"] = quad
    return record


def config_file(work, angle):
    """QuadWild's basic setup with the feature angle (180: no features)."""
    path = os.path.join(work, "setup.txt")
    with open(path, "w") as f:
        f.write("do_remesh 1\nsharp_feature_thr %s\nalpha 0.01\nscaleFact 1\n" % (angle if angle else 180))
    return path


def one_mesh(args, mesh, angle):
    name = os.path.splitext(os.path.basename(mesh))[0] + ("_f%s" % angle if angle else "_nofeatures")
    results = {"mesh": os.path.basename(mesh), "feature_angle": angle}
    label = "_".join(args.field_options.split()).strip("-") + ("_remeshed" if args.on_remeshed else "")
    for field in ("quadwild", "package"):  # QuadWild's own first: --on-remeshed takes its remeshed mesh
        work = os.path.join(args.work, name, field + ("_" + label if field == "package" and label else ""))
        if field == "quadwild" and args.reuse_own and os.path.exists(os.path.join(work, "record.json")):
            results[field] = json.load(open(os.path.join(work, "record.json")))
            continue
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        mesh_obj = os.path.join(work, "M.obj")
        source = mesh
        if field == "package" and args.on_remeshed:
            source = os.path.join(args.work, name, "quadwild", "M_rem.obj")
        command = [args.program, source, "--on", "faces", "--mesh-out", mesh_obj, "--rosy", os.path.join(work, "M.rosy"),
                   "--sharp", os.path.join(work, "M.sharp"), "--json-file", os.path.join(work, "field.json"), "--quiet"]
        if angle:
            command += ["--feature-angle", str(angle)]
        if field == "package":
            command += args.field_options.split()
        code, seconds = run(command, work, args.timeout, os.path.join(work, "log.txt"))
        if code != 0:
            results[field] = {"failed": "direction_field exit %d" % code}
            continue
        extra = [os.path.join(work, "M.rosy"), os.path.join(work, "M.sharp")] if field == "package" else []
        record = quadwild_steps(args, work, mesh_obj, extra, config_file(work, angle))
        if field == "package":
            record["field_s"] = seconds
            with open(os.path.join(work, "field.json")) as f:
                record["singular_vertices"] = json.load(f)["singular_vertices"]
        if "quad_mesh" in record:
            sharp = os.path.join(work, "M.sharp") if field == "package" else mesh_obj[:-4] + "_rem.sharp"
            remeshed = mesh_obj if field == "package" else mesh_obj[:-4] + "_rem.obj"
            if os.path.exists(sharp) and os.path.exists(remeshed):
                points, _ = read_obj(remeshed)
                tolerance = 1e-4 * np.linalg.norm(points.max(axis=0) - points.min(axis=0))
                segments = sharp_segments(remeshed, sharp)
                record["feature_edges"] = len(segments)
                record["features_kept"] = features_kept(segments, record["quad_mesh"], tolerance)
        results[field] = record
        with open(os.path.join(work, "record.json"), "w") as f:
            json.dump(record, f)
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quadwild", required=True, help="build_quadwild.sh's OUT folder (bin/ and src/)")
    parser.add_argument("--program", required=True, help="the direction_field program")
    parser.add_argument("--feature-angles", default="none,35")
    parser.add_argument("--field-options", default="", help="more options of the package's field, e.g. "
                        "'--cancel-singularities 0.07'")
    parser.add_argument("--on-remeshed", action="store_true", help="the package's field on QuadWild's own remeshed "
                        "mesh (M_rem.obj of its first step), so that both fields are on one mesh")
    parser.add_argument("--work", default=os.path.join(tempfile.gettempdir(), "quad_meshing"),
                        help="where the runs' files go (default: quad_meshing in the temporary folder)")
    parser.add_argument("--reuse-own", action="store_true", help="take QuadWild's own results from an earlier run "
                        "in the same --work folder (they do not depend on the package)")
    parser.add_argument("--timeout", type=float, default=1800.)
    parser.add_argument("--json", help="write all results here")
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()
    args.quadwild, args.program = os.path.abspath(args.quadwild), os.path.abspath(args.program)
    angles = [None if a == "none" else float(a) for a in args.feature_angles.split(",")]
    all_results = []
    print("mesh feature_angle | package: irregular quads features_kept field_s qw_s qfp_s | "
          "quadwild's own: irregular quads features_kept qw_s qfp_s | ratio")
    for mesh in args.meshes:
        for angle in angles:
            r = one_mesh(args, mesh, angle)
            all_results.append(r)
            p, q = r.get("package", {}), r.get("quadwild", {})
            def cells(x, keys):
                return " ".join(str(x.get(k, x.get("failed", "-"))) if not isinstance(x.get(k), float)
                                else "%.3g" % x[k] for k in keys)
            ratio = ("%.2f" % (p["irregular"] / q["irregular"])) if "irregular" in p and q.get("irregular") else "-"
            print("%s %s | %s | %s | %s" % (r["mesh"], angle or "none",
                                            cells(p, ["irregular", "quads", "features_kept", "field_s", "quadwild_s",
                                                      "quad_from_patches_s"]),
                                            cells(q, ["irregular", "quads", "features_kept", "quadwild_s",
                                                      "quad_from_patches_s"]), ratio), flush=True)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(all_results, f, indent=1)


if __name__ == "__main__":
    sys.exit(main())
