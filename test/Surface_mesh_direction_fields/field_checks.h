// Helpers shared by the tests: output maps, independent vertex normals (and
// the package's at folded triangles),
// angles between n-directions, and the check of a documented error.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_FIELD_CHECKS_H
#define SURFACE_MESH_DIRECTION_FIELDS_FIELD_CHECKS_H

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/folded_fans.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

// A direction map of a Surface_mesh, initialized to the zero vector.
template <typename Mesh>
auto direction_map(Mesh& mesh, const std::string& name = "v:direction")
{
  typedef typename CGAL::Kernel_traits<typename Mesh::Point>::Kernel::Vector_3 Vector_3;
  return mesh.template add_property_map<typename Mesh::Vertex_index, Vector_3>(name, CGAL::NULL_VECTOR).first;
}

// Angle-weighted vertex normals, computed here independently of the package
// (indexed by vertex index; the zero vector at isolated vertices).
template <typename Mesh>
auto angle_weighted_normals(const Mesh& mesh)
{
  typedef typename CGAL::Kernel_traits<typename Mesh::Point>::Kernel::Vector_3 Vector_3;
  std::vector<Vector_3> normals(mesh.number_of_vertices(), CGAL::NULL_VECTOR);
  for(auto f : mesh.faces())
  {
    auto h = mesh.halfedge(f);
    for(int c = 0; c < 3; ++c, h = mesh.next(h))
    {
      const auto& p = mesh.point(mesh.source(h));
      const Vector_3 a = mesh.point(mesh.target(h)) - p, b = mesh.point(mesh.source(mesh.prev(h))) - p;
      const Vector_3 n = CGAL::cross_product(a, b);
      const double length = std::sqrt(n.squared_length());
      if(length > 0.) normals[mesh.source(h)] = normals[mesh.source(h)] + std::atan2(length, a * b) * n / length;
    }
  }
  for(Vector_3& n : normals)
    if(n != CGAL::NULL_VECTOR) n = n / std::sqrt(n.squared_length());
  return normals;
}

// The normals the package's outputs are orthogonal to by default: the
// angle-weighted normals above, except at the vertices of folded triangles,
// where the package takes the fitted surface's normal (user manual, "Folded
// Triangles"; the replaced ones are those of the package's own function).
// `folded`, if given, receives which vertices those are.
template <typename Mesh>
auto package_normals(const Mesh& mesh, std::vector<bool>* folded = nullptr)
{
  namespace I = CGAL::Surface_mesh_direction_fields::internal;
  typedef typename CGAL::Kernel_traits<typename Mesh::Point>::Kernel::Vector_3 Vector_3;
  std::vector<Vector_3> normals = angle_weighted_normals(mesh);
  I::Indexed_mesh m = I::make_indexed_mesh(
    mesh, [&mesh](typename Mesh::Vertex_index v) { const auto& p = mesh.point(v); return I::Vec3{p.x(), p.y(), p.z()}; },
    get(CGAL::vertex_index, mesh), get(CGAL::face_index, mesh));
  I::Tangent_spaces ts = I::compute_tangent_spaces(m, 1e-6);
  std::vector<I::Vec3> ours(normals.size());
  for(std::size_t v = 0; v < normals.size(); ++v) ours[v] = {normals[v].x(), normals[v].y(), normals[v].z()};
  I::lay_out_folded_fans(m, ours, true, ts);
  if(folded != nullptr) folded->assign(normals.size(), false);
  for(std::size_t v = 0; v < normals.size(); ++v)
    if(ts.projected_fan[v])
    {
      normals[v] = Vector_3(ours[v][0], ours[v][1], ours[v][2]);
      if(folded != nullptr) (*folded)[v] = true;
    }
  return normals;
}

// The angle between two n-directions (modulo 2 pi / n), in [0, pi / n].
template <typename Vector_3>
double angle_mod(const Vector_3& a, const Vector_3& b, int n)
{
  const double c = a * b, s = std::sqrt(CGAL::cross_product(a, b).squared_length());
  return std::abs(std::remainder(n * std::atan2(s, c), 2. * CGAL_PI)) / n;
}

// true if f() throws the package's Invalid_input_error (its message is shown).
template <typename F>
bool throws_invalid_input(F f)
{
  try { f(); }
  catch(const CGAL::Surface_mesh_direction_fields::Invalid_input_error& e)
  { std::cout << "  expected error: " << e.what() << "\n"; return true; }
  catch(...) { return false; }
  return false;
}

#endif
