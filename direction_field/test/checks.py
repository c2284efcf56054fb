"""The checks of the Python tests: each one counted, a failure printed at
once, a summary line and the exit status at the end (imported from the
test's own folder)."""
import os
import math
import sys

# Open MPI refuses root without the first two; more ranks than cores need the
# third (--oversubscribe); one BLAS thread per process.
MPI_ENVIRONMENT = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                       OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")


class Checks:
    def __init__(self):
        self.count = 0
        self.failures = []
        self.skipped = []

    def skip(self, what):
        """A part left out (a shared mesh missing): the test then reports SKIP
        to CTest (exit status 77, SKIP_RETURN_CODE) unless a check failed."""
        self.skipped.append(what)
        print("SKIPPED:", what)

    def __call__(self, ok, what):
        self.count += 1
        if not ok:
            self.failures.append(what)
            print("FAILED:", what)
        return ok

    def finish(self):
        print("%d checks, %d failed, %d parts skipped" % (self.count, len(self.failures), len(self.skipped)))
        sys.exit(1 if self.failures else 77 if self.skipped else 0)


def bumpy_sphere(levels=3):
    """The refined octahedron with each coordinate moved by up to 5% (a fixed
    pattern): no symmetry, so its smoothest fields are unique (a round
    sphere's lowest eigenvalue is repeated, and which field of that
    eigenspace a solve returns depends on its rounding)."""
    points, faces = refined_octahedron(levels)
    return [tuple(x * (1 + 0.05 * math.sin(12.9898 * i + 78.233 * k)) for k, x in enumerate(p))
            for i, p in enumerate(points)], faces


def refined_octahedron(levels=3):
    """The octahedron with each triangle split in four `levels` times, every
    point on the unit sphere: (points, triangles)."""
    points = [(1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, -1.0)]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    for _ in range(levels):
        middle, refined = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = [(x + y) / 2 for x, y in zip(points[a], points[b])]
                length = sum(x * x for x in p) ** 0.5
                points.append(tuple(x / length for x in p))
                middle[key] = len(points) - 1
            return middle[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            refined += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = refined
    return points, faces
