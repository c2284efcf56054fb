// The cost of placing singularities (named parameter
// prescribed_singularities) against the smoothest field, per mesh, in one
// run: the smoothest cross field (free function), the first prescription of
// its own singular faces on a Globally_optimal_direction_field (mesh work,
// cycle basis and the face Laplacian's factorization included), then edits
// on that object: one singularity moved to a neighbouring face and back.
// Rows alternate the three, `--repeat R` times; medians are printed, and the
// ratio edit / smoothest (the editing target: <= 0.1 at 400,000 faces).
// Last, a dense random prescription (the field's own singular faces plus
// one +1 and one -1 per 50 faces, at random): its refusal (or, rarely, its
// field) against an accepted edit (the target: at most an edit's time plus
// a local check).
//
// With --faces: the same for fields on faces (run_on_faces()).
//
//   usage: benchmark_prescription [--faces] [--degree N] [--repeat R] [MESH...]
// With no mesh: nefertiti.off and nefertiti_sub4.off of ../shared/data/meshes.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index Face_index;
namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace params = CGAL::parameters;
typedef std::vector<std::pair<Face_index, int> > Singularities;

static double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0. : v[v.size() / 2];
}

static double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A neighbour of f that is not singular (the edit moves f's singularity there).
static Face_index free_neighbour(const Mesh& mesh, Face_index f, const Singularities& s)
{
  for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
  {
    const Face_index g = mesh.face(mesh.opposite(h));
    if(g == Mesh::null_face()) continue;
    if(std::none_of(s.begin(), s.end(), [&](const auto& fk) { return fk.first == g; })) return g;
  }
  return f;
}

// The field's own singular faces and, on one face in 25 of the others, +1
// and -1 in turn (the sum unchanged), drawn with `seed`.
static Singularities dense_random(const Mesh& mesh, const Singularities& own, unsigned int seed)
{
  std::vector<unsigned char> taken(mesh.number_of_faces(), 0);
  for(const auto& fk : own) taken[std::size_t(fk.first)] = 1;
  Singularities s = own;
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::size_t> face(0, mesh.number_of_faces() - 1);
  for(std::size_t i = 0; i < mesh.number_of_faces() / 25; ++i)
  {
    const std::size_t f = face(random);
    if(taken[f]) continue;
    taken[f] = 1;
    s.emplace_back(Face_index(static_cast<Mesh::size_type>(f)), i % 2 == 0 ? 1 : -1);
  }
  if((s.size() - own.size()) % 2 == 1) s.pop_back();
  return s;
}

static void run(const std::string& path, int degree, int repeat)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh)) { std::cerr << "cannot read " << path << "\n"; return; }
  auto dir = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:direction").first;
  std::vector<double> smoothest, first, edit, dense;
  std::size_t edits_exact = 0, edits = 0, refusals = 0;
  for(int r = 0; r < repeat; ++r)
  {
    Singularities s;
    auto start = std::chrono::steady_clock::now();
    SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(degree).singularities_output_iterator(std::back_inserter(s)));
    smoothest.push_back(milliseconds_since(start));

    start = std::chrono::steady_clock::now();
    SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
    field.compute(dir, params::degree(degree).prescribed_singularities(s));
    first.push_back(milliseconds_since(start));

    Singularities moved = s;
    for(std::size_t i = 0; i < moved.size() && i < 10; ++i)
    {
      const Face_index from = moved[i].first;
      moved[i].first = free_neighbour(mesh, from, moved);
      for(int back = 0; back < 2; ++back)
      {
        Singularities found;
        start = std::chrono::steady_clock::now();
        try
        {
          field.compute(dir, params::degree(degree).prescribed_singularities(moved)
                               .singularities_output_iterator(std::back_inserter(found)));
          edit.push_back(milliseconds_since(start));
          std::sort(found.begin(), found.end());
          Singularities wanted = moved;
          std::sort(wanted.begin(), wanted.end());
          edits_exact += (found == wanted);
        }
        catch(const SMDF::Invalid_input_error&) {}  // a move that no field on the vertices can show
        ++edits;
        moved[i].first = from;
      }
    }
    start = std::chrono::steady_clock::now();
    try { field.compute(dir, params::degree(degree).prescribed_singularities(dense_random(mesh, s, r))); }
    catch(const SMDF::Invalid_input_error&) { ++refusals; }
    dense.push_back(milliseconds_since(start));
  }
  const double ratio = median(edit) / median(smoothest);
  std::printf("%-24s %8zu faces  smoothest %8.1f ms  first prescription %8.1f ms  edit %7.1f ms  edit/smoothest %.3f"
              "  (%zu of %zu edits exact)\n",
              path.substr(path.find_last_of('/') + 1).c_str(), static_cast<std::size_t>(mesh.number_of_faces()),
              median(smoothest), median(first), median(edit), ratio, edits_exact, edits);
  std::printf("%-24s dense random prescription %8.1f ms (%.2f edits; %zu of %d refused)\n", "",
              median(dense), median(dense) / median(edit), refusals, repeat);
}

typedef std::vector<std::pair<Mesh::Vertex_index, int> > Vertex_singularities;

// An interior neighbour of v that is not singular.
static Mesh::Vertex_index free_vertex_neighbour(const Mesh& mesh, Mesh::Vertex_index v, const Vertex_singularities& s)
{
  for(auto w : CGAL::vertices_around_target(mesh.halfedge(v), mesh))
    if(!mesh.is_border(w) && std::none_of(s.begin(), s.end(), [&](const auto& vk) { return vk.first == w; }))
      return w;
  return v;
}

// --faces: the same rows for fields on faces (singularities at vertices): the
// smoothest field (free function), the first prescription of its own singular
// vertices on a Globally_optimal_face_direction_field (construction, trees
// and the factorization of the faces' Laplacian included), then edits.
static void run_on_faces(const std::string& path, int degree, int repeat)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh)) { std::cerr << "cannot read " << path << "\n"; return; }
  auto dir = mesh.add_property_map<Face_index, Kernel::Vector_3>("f:direction").first;
  std::vector<double> smoothest, first, edit;
  std::size_t edits_exact = 0, edits = 0;
  for(int r = 0; r < repeat; ++r)
  {
    Vertex_singularities s;
    auto start = std::chrono::steady_clock::now();
    SMDF::compute_globally_optimal_face_directions(mesh, dir, params::degree(degree).singularities_output_iterator(std::back_inserter(s)));
    smoothest.push_back(milliseconds_since(start));
    start = std::chrono::steady_clock::now();
    const SMDF::Globally_optimal_face_direction_field<Mesh> field(mesh);
    field.compute(dir, params::degree(degree).prescribed_singularities(s));
    first.push_back(milliseconds_since(start));
    Vertex_singularities moved = s;
    for(std::size_t i = 0; i < moved.size() && i < 10; ++i)
    {
      const Mesh::Vertex_index from = moved[i].first;
      moved[i].first = free_vertex_neighbour(mesh, from, moved);
      for(int back = 0; back < 2; ++back)
      {
        Vertex_singularities found;
        start = std::chrono::steady_clock::now();
        field.compute(dir, params::degree(degree).prescribed_singularities(moved)
                             .singularities_output_iterator(std::back_inserter(found)));
        edit.push_back(milliseconds_since(start));
        std::sort(found.begin(), found.end());
        Vertex_singularities wanted = moved;
        std::sort(wanted.begin(), wanted.end());
        edits_exact += (found == wanted);
        ++edits;
        moved[i].first = from;
      }
    }
  }
  std::printf("%-24s %8zu faces  on faces: smoothest %8.1f ms  first prescription %8.1f ms (%.3f)  edit %7.1f ms"
              "  edit/smoothest %.3f  (%zu of %zu edits exact)\n",
              path.substr(path.find_last_of('/') + 1).c_str(), static_cast<std::size_t>(mesh.number_of_faces()),
              median(smoothest), median(first), median(first) / median(smoothest), median(edit),
              median(edit) / median(smoothest), edits_exact, edits);
}

int main(int argc, char** argv)
{
  int degree = 4, repeat = 3;
  bool on_faces = false;
  std::vector<std::string> meshes;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--degree" && i + 1 < argc) degree = std::stoi(argv[++i]);
    else if(a == "--repeat" && i + 1 < argc) repeat = std::stoi(argv[++i]);
    else if(a == "--faces") on_faces = true;
    else meshes.push_back(a);
  }
  if(meshes.empty())
    for(const char* name : {"nefertiti.off", "nefertiti_sub4.off"})
      meshes.push_back(std::string(SMDF_SHARED_MESH_DIR) + "/" + name);
  for(const std::string& m : meshes)
    on_faces ? run_on_faces(m, degree, repeat) : run(m, degree, repeat);
  return 0;
}
