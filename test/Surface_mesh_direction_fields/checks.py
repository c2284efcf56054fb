"""The checks of the Python tests: each one counted, a failure printed at
once, a summary line and the exit status at the end (imported from the
test's own folder)."""
import os
import sys

# Open MPI refuses root without the first two; more ranks than cores need the
# third (--oversubscribe); one BLAS thread per process.
MPI_ENVIRONMENT = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                       OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")


class Checks:
    def __init__(self):
        self.count = 0
        self.failures = []

    def __call__(self, ok, what):
        self.count += 1
        if not ok:
            self.failures.append(what)
            print("FAILED:", what)
        return ok

    def finish(self):
        print("%d checks, %d failed" % (self.count, len(self.failures)))
        sys.exit(1 if self.failures else 0)
