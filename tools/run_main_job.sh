#!/usr/bin/env bash
# The main job: the smoothest cross field of CGAL's fandisk (or of the mesh
# given as first argument), written to build/main_job/: directions,
# singularities, a JSON summary and a picture.
#   usage: tools/run_main_job.sh [MESH] [direction_field options...]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh main
mkdir -p build
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build/main_job.log 2>&1 || { cat build/main_job.log; exit 1; }
cmake --build build --target direction_field -j "$(nproc)" >> build/main_job.log 2>&1 || { cat build/main_job.log; exit 1; }
mkdir -p build/main_job
out=build/main_job
build/bin/direction_field "$@" --directions $out/directions.txt --singularities $out/singularities.txt \
                                --png $out/field.png --vtk $out/field.vtk --json-file $out/summary.json \
                                --streamlines $out/streamlines.vtp
echo
echo "Wrote $out/directions.txt (one unit vector per vertex), $out/singularities.txt (face, index k of k/n),"
echo "      $out/summary.json, the picture $out/field.png and $out/field.vtk (ParaView: all n directions,"
echo "      magnitude, singularities with their index), $out/streamlines.vtp (field lines, drawn in the picture)"
