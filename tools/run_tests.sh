#!/usr/bin/env bash
# The whole test suite: builds the examples and tests (Release; the tests'
# checks do not depend on assert) and runs them with CTest, including the
# examples, the command-line contract and the Doxygen check.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh tests
jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSMDF_BUILD_TESTS=ON -DSMDF_BUILD_BENCHMARKS=ON
cmake --build build -j "$jobs"
cd build
ctest --output-on-failure -j "$jobs"
