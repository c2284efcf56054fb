#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer: a
# separate build in build-sanitizers/ (-O1, -fsanitize=address,undefined,float-cast-overflow, any
# report is fatal) of the command-line program and the tests of files,
# input and memory, then those tests (the command line, hostile input,
# fuzzing, file formats, robustness, the linear algebra, the solver and the
# tangent spaces at folded triangles).
# Not part of CI's test command (the build alone takes longer than CI's
# budget allows); run it before resolving an issue that touches input,
# output or memory.
#   usage: tools/run_sanitizers.sh [ctest -R regex]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh tests
flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all"
cmake -S . -B build-sanitizers -DCMAKE_BUILD_TYPE=None -DSMDF_BUILD_TESTS=ON -DSMDF_BUILD_DOC=OFF \
      -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined,float-cast-overflow" > /dev/null
targets="direction_field test_mesh_files test_io test_robustness test_linear_algebra test_prescribed_singularities test_matrices test_folded_triangulations"
cmake --build build-sanitizers -j "$(nproc)" --target $targets
cd build-sanitizers
# ASan reserves terabytes of address space: the hostile-input test's memory limit cannot apply.
export SMDF_NO_MEMORY_LIMIT=1
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --output-on-failure -j "$(nproc)" \
      -R "${1:-test_command_line|test_hostile_input|test_fuzz_command_line|test_mesh_files|test_io|test_exchange_readers|test_linear_algebra|test_robustness$|test_prescribed_singularities|test_matrices$|test_folded_triangulations}"
