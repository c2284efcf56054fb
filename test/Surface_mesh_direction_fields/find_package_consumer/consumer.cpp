// Uses the installed package: a vector field on a tetrahedron (index sum 2).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <iostream>

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main()
{
  Mesh m;
  auto a = m.add_vertex(K::Point_3(1, 1, 1)), b = m.add_vertex(K::Point_3(1, -1, -1)),
       c = m.add_vertex(K::Point_3(-1, 1, -1)), d = m.add_vertex(K::Point_3(-1, -1, 1));
  m.add_face(a, b, c); m.add_face(a, c, d); m.add_face(a, d, b); m.add_face(b, d, c);
  auto dir = m.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:d").first;
  const auto r = CGAL::Surface_mesh_direction_fields::compute_globally_optimal_directions(
    m, dir, CGAL::parameters::degree(1));
  std::cout << "index sum " << r.index_sum << std::endl;
  return r.index_sum == 2 ? 0 : 1;
}
