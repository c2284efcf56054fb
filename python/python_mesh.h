// The module's types and its mesh: numpy arrays (V, F) as a Surface_mesh,
// refused with a ValueError that says why.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PYTHON_MESH_H
#define SURFACE_MESH_DIRECTION_FIELDS_PYTHON_MESH_H

#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/Globally_optimal_direction_field.h>
#include <CGAL/Surface_mesh_direction_fields/globally_optimal_directions.h>
#include <CGAL/Surface_mesh_direction_fields/openblas_thread_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Edge_index Edge_index;
typedef SMDF::Globally_optimal_direction_field<Mesh> Field;
typedef py::array_t<double, py::array::c_style | py::array::forcecast> Float_array;
typedef py::array_t<long long, py::array::c_style | py::array::forcecast> Index_array;

#include "file_io/read_and_repair_mesh.h"

namespace {

[[noreturn]] void refuse(const std::string& message) { throw py::value_error(message); }

// +1 if the triangle runs along `edge` from its first vertex to its second, -1 otherwise.
inline int direction_in(const long long* t, const std::pair<long long, long long>& edge)
{
  for(int c = 0; c < 3; ++c)
    if(t[c] == edge.first && t[(c + 1) % 3] == edge.second) return 1;
  return -1;
}

// The rows of a C-contiguous (n, 3) numpy array, as build_oriented_manifold()
// reads them: the mesh is built from the arrays without another copy.
template <typename T>
struct Rows_of_three
{
  const T* data;
  std::size_t rows;
  std::size_t size() const { return rows; }
  const T* operator[](std::size_t i) const { return data + 3 * i; }
};

// Why triangles that build_oriented_manifold() refused are not an oriented
// manifold, naming the faces where it can: two faces using one edge in the
// same direction (one of them is flipped), or an edge of more than two faces.
inline std::string why_not_an_oriented_manifold(const Rows_of_three<long long>& triangles)
{
  std::map<std::pair<long long, long long>, std::vector<std::size_t> > faces_of_edge;  // undirected edge
  for(std::size_t f = 0; f < triangles.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const long long a = triangles[f][c], b = triangles[f][(c + 1) % 3];
      faces_of_edge[std::minmax(a, b)].push_back(f);
    }
  for(const auto& [edge, faces] : faces_of_edge)
  {
    if(faces.size() > 2)
      return "the edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) + " belongs to " +
             std::to_string(faces.size()) + " faces (F rows " + std::to_string(faces[0]) + ", " +
             std::to_string(faces[1]) + ", " + std::to_string(faces[2]) + (faces.size() > 3 ? ", ..." : "") + ")";
    if(faces.size() == 2 && direction_in(triangles[faces[0]], edge) == direction_in(triangles[faces[1]], edge))
      return "F rows " + std::to_string(faces[0]) + " and " + std::to_string(faces[1]) + " run along the edge " +
             std::to_string(edge.first) + "-" + std::to_string(edge.second) +
             " in the same direction: one of them is flipped (or they repeat one face)";
  }
  return "the faces do not form an oriented manifold mesh (a pinched vertex: its faces form more than one fan)";
}

// V (|V| x 3, finite) and F (|F| x 3 indices into V) as a Surface_mesh, built
// as the command-line program builds a clean file's mesh (the same halfedges,
// hence the same field bit for bit); the faces must already form an oriented
// manifold (read_mesh() repairs files).
Mesh make_mesh(const Float_array& V, const Index_array& F)
{
  namespace rr = read_and_repair_internal;
  if(V.ndim() != 2 || V.shape(1) != 3) refuse("V must be an array of shape (number of vertices, 3)");
  if(F.ndim() != 2 || F.shape(1) != 3) refuse("F must be an array of shape (number of faces, 3): triangles");
  if(V.shape(0) == 0 || F.shape(0) == 0) refuse("the mesh is empty (V and F need at least one row)");
  const Rows_of_three<double> points{V.data(), static_cast<std::size_t>(V.shape(0))};
  const Rows_of_three<long long> triangles{F.data(), static_cast<std::size_t>(F.shape(0))};
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(points[i][c])) refuse("V row " + std::to_string(i) + " has a non-finite coordinate");
  for(std::size_t i = 0; i < triangles.size(); ++i)
  {
    const long long* t = triangles[i];
    for(int c = 0; c < 3; ++c)
      if(t[c] < 0 || t[c] >= V.shape(0))
        refuse("F row " + std::to_string(i) + " refers to vertex " + std::to_string(t[c]) + ", not in V");
    if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) refuse("F row " + std::to_string(i) + " repeats a vertex");
  }
  Mesh mesh;
  bool built = false;
  try { built = rr::build_oriented_manifold(points, triangles, mesh); }
  catch(const Mesh_input_error& e) { refuse(e.what()); }
  if(!built) refuse(why_not_an_oriented_manifold(triangles) + "; read_mesh() repairs mesh files");
  return mesh;
}

}  // namespace

#endif // SURFACE_MESH_DIRECTION_FIELDS_PYTHON_MESH_H
