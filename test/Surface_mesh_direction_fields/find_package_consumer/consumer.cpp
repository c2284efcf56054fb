// Uses the installed package: a vector field on a tetrahedron (index sum 2),
// a cross field and a curvature-aligned line field on a torus (index sums 0).
// Built twice by the consumer project, header-only and against the compiled
// engine; both print the same digest of every direction, bit for bit.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/version.h>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

// FNV-1a over the bytes of every coordinate of every direction
template <typename Map>
std::uint64_t digest(const Mesh& m, const Map& dir)
{
  std::uint64_t h = 14695981039346656037ull;
  for(Vertex v : m.vertices())
    for(int c = 0; c < 3; ++c)
    {
      const double x = get(dir, v)[c];
      unsigned char bytes[sizeof(double)];
      std::memcpy(bytes, &x, sizeof(double));
      for(unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
    }
  return h;
}

Mesh bumpy_torus(int nu, int nv)
{
  Mesh m;
  const double pi = std::acos(-1.);
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double u = 2 * pi * i / nu, w = 2 * pi * j / nv, r = 0.4 + 0.05 * std::sin(3 * u);
      m.add_vertex(K::Point_3((1 + r * std::cos(w)) * std::cos(u), (1 + r * std::cos(w)) * std::sin(u), r * std::sin(w)));
    }
  auto at = [&](int i, int j) { return Vertex(static_cast<Mesh::size_type>(((i + nu) % nu) * nv + (j + nv) % nv)); };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

int main()
{
  Mesh tet;
  auto a = tet.add_vertex(K::Point_3(1, 1, 1)), b = tet.add_vertex(K::Point_3(1, -1, -1)),
       c = tet.add_vertex(K::Point_3(-1, 1, -1)), d = tet.add_vertex(K::Point_3(-1, -1, 1));
  tet.add_face(a, b, c); tet.add_face(a, c, d); tet.add_face(a, d, b); tet.add_face(b, d, c);
  auto tet_dir = tet.add_property_map<Vertex, K::Vector_3>("v:d").first;
  const auto r1 = SMDF::compute_globally_optimal_directions(tet, tet_dir, CGAL::parameters::degree(1));

  Mesh torus = bumpy_torus(48, 20);
  auto dir = torus.add_property_map<Vertex, K::Vector_3>("v:d").first;
  const auto r4 = SMDF::compute_globally_optimal_directions(torus, dir, CGAL::parameters::degree(4));
  const std::uint64_t cross = digest(torus, dir);
  SMDF::Globally_optimal_direction_field<Mesh> field(torus);
  const auto r2 = field.compute(dir, CGAL::parameters::degree(2)
                                       .principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM)
                                       .alignment_weight(0.5));
  std::cout << "CGAL " << CGAL_VERSION_STR << ": index sums " << r1.index_sum << " " << r4.index_sum << " " << r2.index_sum << ", digests " << std::hex
            << digest(tet, tet_dir) << " " << cross << " " << digest(torus, dir) << std::endl;
  return r1.index_sum == 2 && r4.index_sum == 0 && r2.index_sum == 0 ? 0 : 1;
}
