// geometry-central's field on faces, timed as the package's is: reads a mesh,
// then times computeSmoothestFaceDirectionField (degree N) and
// computeVertexIndex (its singular vertices). Prints one line:
//   RESULT tool=gc mode=smooth_faces V=.. F=.. n=.. time_ms=.. field_ms=.. nSingVertices=.. indexSum=.. reps=.. times_ms=..
// time_ms is the median over --reps, each on a freshly read mesh; reading is not timed.
//
//   usage: gc_face_driver MESH N [--reps=K]
// Built against the geometry-central tree of ../shared/tools/reference_implementations
// (build_anchors.sh gc) by this folder's CMakeLists.txt; not part of the package.
#include "geometrycentral/surface/direction_fields.h"
#include "geometrycentral/surface/meshio.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace geometrycentral;
using namespace geometrycentral::surface;

int main(int argc, char** argv)
{
  if(argc < 3) { std::cerr << "usage: gc_face_driver MESH N [--reps=K]\n"; return 2; }
  const std::string path = argv[1];
  const int n = std::stoi(argv[2]);
  int reps = 1;
  for(int i = 3; i < argc; ++i)
    if(std::string(argv[i]).rfind("--reps=", 0) == 0) reps = std::stoi(std::string(argv[i]).substr(7));
  std::vector<double> times, field_times;
  std::size_t nv = 0, nf = 0;
  int singular = 0, index_sum = 0;
  for(int r = 0; r < reps; ++r)
  {
    std::unique_ptr<ManifoldSurfaceMesh> mesh;
    std::unique_ptr<VertexPositionGeometry> geometry;
    std::tie(mesh, geometry) = readManifoldSurfaceMesh(path);
    nv = mesh->nVertices();
    nf = mesh->nFaces();
    const auto t0 = std::chrono::steady_clock::now();
    FaceData<Vector2> field = computeSmoothestFaceDirectionField(*geometry, n);
    const auto t1 = std::chrono::steady_clock::now();
    VertexData<int> index = computeVertexIndex(*geometry, field, n);
    const auto t2 = std::chrono::steady_clock::now();
    times.push_back(std::chrono::duration<double, std::milli>(t2 - t0).count());
    field_times.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    singular = index_sum = 0;
    for(Vertex v : mesh->vertices())
    {
      singular += index[v] != 0;
      index_sum += index[v];
    }
  }
  std::vector<double> sorted = times;
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> sorted_field = field_times;
  std::sort(sorted_field.begin(), sorted_field.end());
  std::printf("RESULT tool=gc mode=smooth_faces V=%zu F=%zu n=%d time_ms=%.3f field_ms=%.3f nSingVertices=%d indexSum=%d reps=%d times_ms=",
              nv, nf, n, sorted[sorted.size() / 2], sorted_field[sorted_field.size() / 2], singular, index_sum, reps);
  for(std::size_t i = 0; i < times.size(); ++i) std::printf("%s%.3f", i ? "," : "", times[i]);
  std::printf("\n");
  return 0;
}
