#!/usr/bin/env bash
# The whole test suite: builds the examples and tests (Release; the tests'
# checks do not depend on assert) and runs them with CTest, including the
# examples, the command-line contract and the Doxygen check. Then, when the
# CGAL 6.1.1 release tree is beside the project (../shared/cgal), the same
# sources are built against it and the tests that depend on CGAL run there
# too: the library tests, the examples, the viewer, the Python module, the
# find_package consumer, and the program's files compared byte for byte with
# the first build's (the program's own file-handling tests, the tests whose
# subject does not depend on CGAL's version, the tests of build variants,
# assertions on and two default solvers in one program, run once, in the
# first build, as does pip's route). The benchmark programs that only measure
# are not built.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh tests
jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSMDF_BUILD_TESTS=ON -DSMDF_BUILD_BENCHMARKS=ON \
      -DSMDF_BENCHMARKS_TESTED_ONLY=ON
cmake --build build -j "$jobs"
(cd build && ctest --output-on-failure -j "$jobs")

cgal6=../shared/cgal/CGAL-6.1.1
if [ -f "$cgal6/lib/cmake/CGAL/CGALConfig.cmake" ]; then
  echo "== the same sources against CGAL 6.1.1 ($cgal6)"
  start=$(date +%s)
  cmake -S . -B build-cgal6 -DCMAKE_BUILD_TYPE=Release -DSMDF_BUILD_TESTS=ON \
        -DCGAL_DIR="$(cd "$cgal6" && pwd)" -DSMDF_REFERENCE_PROGRAM="$PWD/build/bin/direction_field" \
        -DSMDF_TESTS_WITHOUT_CGAL=OFF -DSMDF_HEADER_ONLY_CONSUMER=OFF -DSMDF_BUILD_VARIANT_TESTS=OFF
  cmake --build build-cgal6 -j "$jobs"
  (cd build-cgal6 && ctest --output-on-failure -j "$jobs" -LE "program|packaging")
  echo "== CGAL 6.1.1 build and tests: $(( $(date +%s) - start )) s"
else
  echo "== CGAL 6.1.1 not found at $cgal6: the second build (against CGAL 6) is skipped"
fi
