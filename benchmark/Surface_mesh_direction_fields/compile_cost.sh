#!/usr/bin/env bash
# What one consumer file costs to compile (-O3, as a Release build): a cross
# field on a CGAL::Surface_mesh through this package, header-only ("cross")
# and as a program linking CGAL::Surface_mesh_direction_fields_compiled
# compiles it ("compiled": the engine's definitions left out), against the
# same kind of file computing geodesic distances with CGAL's Heat_method_3,
# compiled in turn (interleaved, REPS times) on this machine. Prints the best
# time and the peak memory of each and their ratios to Heat_method_3.
#   usage: benchmark/Surface_mesh_direction_fields/compile_cost.sh [REPS]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
reps="${1:-2}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
common='#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <fstream>
#include <iostream>
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor Vertex;
int main(int argc, char* argv[])
{
  Mesh mesh;
  std::ifstream in(argc > 1 ? argv[1] : "mesh.off");
  in >> mesh;'
printf '%s\n' '#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>' "$common" \
  '  auto distance = mesh.add_property_map<Vertex, double>("v:distance", 0).first;' \
  '  CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Mesh> heat(mesh);' \
  '  heat.add_source(*vertices(mesh).first);' \
  '  heat.estimate_geodesic_distances(distance);' \
  '  for(Vertex v : vertices(mesh)) std::cout << get(distance, v) << "\n";' '}' > "$work/heat.cpp"
printf '%s\n' '#include <CGAL/Surface_mesh_direction_fields/globally_optimal_directions.h>' "$common" \
  '  auto direction = mesh.add_property_map<Vertex, K::Vector_3>("v:direction").first;' \
  '  CGAL::Surface_mesh_direction_fields::compute_globally_optimal_directions(mesh, direction,' \
  '                                                                             CGAL::parameters::degree(4));' \
  '  for(Vertex v : vertices(mesh)) std::cout << get(direction, v) << "\n";' '}' > "$work/cross.cpp"
# the definitions and include folders a find_package consumer gets on Debian
flags="-std=c++17 -O3 -DNDEBUG -DCGAL_EIGEN3_ENABLED -I$root/include -isystem /usr/include/eigen3
       -isystem /usr/include/suitesparse -isystem /usr/include/x86_64-linux-gnu/openblas-pthread
       -DCGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD -DCGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS
       -DCGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_OPENBLAS_THREADS"
for rep in $(seq "$reps"); do
  for f in heat cross compiled; do
    source="$work/$f.cpp" extra=""
    if [ "$f" = compiled ]; then
      source="$work/cross.cpp" extra="-DCGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION"
    fi
    /usr/bin/time -f "$f %e %M" -a -o "$work/times" g++ $flags $extra -w -c "$source" -o "$work/$f.o"
  done
done
python3 - "$work/times" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1])]
best = {f: (min(float(r[1]) for r in rows if r[0] == f), max(int(r[2]) for r in rows if r[0] == f) / 1024.)
        for f in ("heat", "cross", "compiled")}
for f, (s, mb) in best.items():
    print("%-9s %6.1f s %7.0f MB   (best time, peak memory over the runs)" % (f, s, mb))
for f in ("cross", "compiled"):
    print("%-9s ratio to heat %5.2f  %5.2f" % (f, best[f][0] / best["heat"][0], best[f][1] / best["heat"][1]))
PY
