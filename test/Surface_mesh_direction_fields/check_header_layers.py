#!/usr/bin/env python3
"""The layers of the package's headers, as the README states them, and the
size of the documents that explain them.

Every header of include/CGAL/Surface_mesh_direction_fields belongs to one
layer, and includes (directly) only headers of the layers it may use. As every
layer's rule is closed downwards, the direct includes decide the transitive
ones too. (That each header also compiles on its own is the build of the
target test_headers_alone.)

    python3 check_header_layers.py INCLUDE_DIR
"""
import pathlib
import re
import sys

VOCABULARY = {"exceptions.h", "alignment.h", "Direction_field_result.h"}  # include nothing of the package
# the solvers' public headers: usable on their own, over the linear algebra and the package's own
# factorization (Supernodal); the engine sees a solver type only, the front end that chooses it includes it
SOLVER = {"Cholmod_supernodal_solver.h"}

# what each layer may include, besides itself
MAY_USE = {
    "vocabulary": set(),
    "base": {"vocabulary"},
    "Linear_algebra": {"vocabulary", "base"},
    "Mesh": {"vocabulary", "base"},
    "Method": {"vocabulary", "base", "Linear_algebra", "Mesh"},
    # the supernodal factorization on CHOLMOD's analysis, its solves and Scotch's ordering: the default
    # solver's code, which only the solver's public header includes
    "Supernodal": {"vocabulary", "base", "Linear_algebra"},
    "solver": {"vocabulary", "base", "Linear_algebra", "Supernodal"},
    "Engine": {"vocabulary", "base", "Linear_algebra", "Mesh", "Method"},
    # the processes' path (PETSc, SLEPc, MPI), behind the engine's Distributed_backend (Method)
    "Distributed": {"vocabulary", "base", "Linear_algebra", "Mesh", "Method"},
    "IO internals": {"vocabulary", "base", "public"},
    "public": None,  # anything
}


def layer_of(relative):
    parts = relative.split("/")
    if len(parts) == 1:
        if parts[0] in VOCABULARY:
            return "vocabulary"
        return "solver" if parts[0] in SOLVER else "public"
    if parts[0] == "internal":
        return "base" if len(parts) == 2 else parts[1]
    if parts[0] == "IO":
        return "IO internals" if parts[1] == "internal" else "public"
    return "public"


# The user manual teaches the method and the README leads a newcomer in: both
# stay short enough to be read (the details live in the reference manual, the
# program's README and benchmark/).
DOCUMENT_LINES = {"doc/Surface_mesh_direction_fields/Surface_mesh_direction_fields.txt": 650, "README.md": 200}


def document_sizes(project):
    failures = []
    for document, limit in DOCUMENT_LINES.items():
        path = project / document
        if not path.exists():
            failures.append(f"{document} is missing")
            continue
        lines = len(path.read_text().splitlines())
        print(f"{document}: {lines} lines (at most {limit})")
        if lines > limit:
            failures.append(f"{document} has {lines} lines, more than {limit}")
    return failures


INCLUDE = re.compile(r'^\s*#\s*include\s*<CGAL/Surface_mesh_direction_fields/([^>]+)>', re.M)


def main():
    root = pathlib.Path(sys.argv[1]) / "CGAL" / "Surface_mesh_direction_fields"
    headers = sorted(str(p.relative_to(root)) for p in root.rglob("*.h"))
    unknown = [h for h in headers if layer_of(h) not in MAY_USE]
    if unknown:
        print("headers outside every layer: " + ", ".join(unknown))
        return 1
    failures = []
    for header in headers:
        layer = layer_of(header)
        allowed = MAY_USE[layer]
        for included in INCLUDE.findall((root / header).read_text()):
            if not (root / included).exists():
                failures.append(f"{header} includes {included}, which does not exist")
                continue
            other = layer_of(included)
            if allowed is not None and other != layer and other not in allowed:
                failures.append(f"{header} ({layer}) includes {included} ({other})")
    counts = {}
    for header in headers:
        counts[layer_of(header)] = counts.get(layer_of(header), 0) + 1
    print("headers per layer: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    for failure in failures:
        print("layer broken: " + failure)
    documents = document_sizes(pathlib.Path(sys.argv[1]).resolve().parent)
    for failure in documents:
        print("document too long: " + failure)
    return 1 if failures or documents else 0


if __name__ == "__main__":
    sys.exit(main())
