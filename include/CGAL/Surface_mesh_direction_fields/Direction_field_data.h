// Copyright (c) 2026  The Surface_mesh_direction_fields authors.
// All rights reserved.
//
// This file is part of CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s)     : The Surface_mesh_direction_fields authors

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_DIRECTION_FIELD_DATA_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_DIRECTION_FIELD_DATA_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vertex_normals.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

// A computed field as plain arrays, shared by the file writers and readers
// (IO/direction_field_files.h), the field lines (streamlines.h) and the viewer
// (draw_direction_field.h). It carries its degree n, so nothing downstream asks
// for n again.

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

A direction field on a triangle mesh as plain arrays, independent of the mesh
class: what the files of this package store, what the field lines and the
viewer read, and what a file is read back into (so that it can be compared
without building a mesh). It carries the field's degree `n`.
*/
struct Direction_field_data
{
  /// a 3D vector or point
  typedef std::array<double, 3> Vector;
  /// the degree `n` of the field
  int degree = 1;
  /// vertex positions
  std::vector<Vector> points;
  /// triangles, as indices into `points`
  std::vector<std::array<std::size_t, 3> > faces;
  /// per vertex, its `n` unit directions (the `k`-th is the first rotated by \f$ 2\pi k / n \f$ about the normal)
  std::vector<std::vector<Vector> > directions;
  /// per vertex, the unit normal about which its directions turn (orthogonal to them)
  std::vector<Vector> normals;
  /// per vertex, the magnitude \f$ |u| \f$ (empty if the file has none)
  std::vector<double> magnitudes;
  /// per face, one unit direction (the per-face files); the others are its rotations in the face plane
  std::vector<Vector> face_directions;
  /// singular faces: face index and integer `k` (the index is `k / n`)
  std::vector<std::pair<std::size_t, int> > singularities;
  /// the barycentre of each singular face, in the order of `singularities`
  std::vector<Vector> singularity_points;
  /// for a field on faces: the singular interior vertices, vertex index and integer `k` (the index is `k / n`)
  std::vector<std::pair<std::size_t, int> > vertex_singularities;
  /// for a field on faces: per face `f` and side `c` (from `faces[f][c]` to `faces[f][(c+1)%3]`), the period
  /// jump from `f` to the face across that side (see `edge_matching_map`); 0 on the boundary
  std::vector<std::array<int, 3> > face_matching;
};

namespace internal {

inline void check_degree(int degree)
{
  if(degree < 1 || degree > maximum_degree)
    throw Invalid_input_error("the degree n must be from 1 to " + std::to_string(maximum_degree) + " (got " +
                              std::to_string(degree) + ")");
}

// The exponent e such that 2^-e brings the largest coordinate of `points`
// to [1/2, 1) where it lies beyond 2^±`limit` (0 elsewhere, and for no or
// non-finite coordinates): products of coordinates (cross products, squared
// lengths) overflow or underflow near 1e±150, and a computation on the
// points times 2^-e, an exact scaling, gives the same unit vectors and the
// same points once scaled back.
inline int extreme_scale_exponent(const std::vector<Vec3>& points, int limit)
{
  double largest = 0.;
  for(const Vec3& p : points)
    for(double x : p) largest = (std::max)(largest, std::abs(x));
  if(!(largest > 0.) || !std::isfinite(largest)) return 0;
  int exponent = 0;
  std::frexp(largest, &exponent);
  return exponent > limit || exponent < -limit ? exponent : 0;
}

inline std::vector<Vec3> scaled_by_power_of_two(std::vector<Vec3> points, int exponent)
{
  for(Vec3& p : points)
    for(double& x : p) x = std::ldexp(x, exponent);
  return points;
}

// Coordinates beyond 2^±400 (about 1e±120) are scaled for the computation of
// normals and per-face directions; meshes of ordinary size keep their bits.
constexpr int extreme_coordinate_exponent = 400;

// The normals of a triangle soup, as the library computes them
// (vertex_normals.h): Euclidean corner angles, the corners of each vertex in
// face order.
inline std::vector<Vec3> angle_weighted_normals(const std::vector<Vec3>& points,
                                                const std::vector<std::array<std::size_t, 3> >& faces)
{
  if(const int e = extreme_scale_exponent(points, extreme_coordinate_exponent))
    return angle_weighted_normals(scaled_by_power_of_two(points, -e), faces);
  std::vector<std::size_t> offset(points.size() + 1, 0), corner_of_vertex(3 * faces.size());
  for(const auto& t : faces)
    for(std::size_t v : t) ++offset[v + 1];
  for(std::size_t v = 0; v < points.size(); ++v) offset[v + 1] += offset[v];
  std::vector<std::size_t> next = offset;
  for(std::size_t corner = 0; corner < 3 * faces.size(); ++corner)
    corner_of_vertex[next[faces[corner / 3][corner % 3]]++] = corner;
  struct Corners
  {
    const std::size_t *first, *last;
    const std::size_t* begin() const { return first; }
    const std::size_t* end() const { return last; }
  };
  auto corners_of = [&](std::size_t v) {
    return Corners{corner_of_vertex.data() + offset[v], corner_of_vertex.data() + offset[v + 1]};
  };
  auto euclidean_angle = [&](std::size_t corner) {
    const auto& t = faces[corner / 3];
    const int c = static_cast<int>(corner % 3);
    const Vec3 a = points[t[(c + 1) % 3]] - points[t[c]], b = points[t[(c + 2) % 3]] - points[t[c]];
    return std::atan2(norm(cross(a, b)), dot(a, b));
  };
  return angle_weighted_vertex_normals(points, faces, corners_of, euclidean_angle);
}

// Normals made orthogonal to each vertex's first direction, and the n
// directions as rotations of the first one about them.
inline void complete_directions(Direction_field_data& data, const std::vector<Vec3>& normal,
                                const std::vector<Vec3>& first)
{
  const std::size_t nv = first.size();
  data.normals.resize(nv);
  data.directions.assign(nv, std::vector<Vec3>(static_cast<std::size_t>(data.degree)));
  for(std::size_t v = 0; v < nv; ++v)
  {
    const Vec3 n = normalized(normal[v] - dot(normal[v], first[v]) * first[v]);
    data.normals[v] = n;
    for(int k = 0; k < data.degree; ++k)
      data.directions[v][static_cast<std::size_t>(k)] = rotated(first[v], n, 2. * CGAL_PI * k / data.degree);
  }
}

template <typename Vector>
Vec3 to_vec3(const Vector& p)
{
  return Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

// The points and triangles of tmesh, in the order of its vertex and face indices.
template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap, typename FaceIndexMap>
void copy_mesh(const TriangleMesh& tmesh, VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim,
               Direction_field_data& data)
{
  data.points.resize(static_cast<std::size_t>(num_vertices(tmesh)));
  for(auto v : vertices(tmesh)) data.points[static_cast<std::size_t>(get(vim, v))] = to_vec3(get(vpm, v));
  data.faces.resize(static_cast<std::size_t>(num_faces(tmesh)));
  for(auto f : faces(tmesh))
  {
    auto& t = data.faces[static_cast<std::size_t>(get(fim, f))];
    int c = 0;
    for(auto v : vertices_around_face(halfedge(f, tmesh), tmesh))
    {
      if(c == 3) throw Invalid_input_error("the mesh has a face that is not a triangle");
      t[static_cast<std::size_t>(c++)] = static_cast<std::size_t>(get(vim, v));
    }
    if(c != 3) throw Invalid_input_error("the mesh has a face that is not a triangle");
  }
}

// The matching per face side, from the jump of each edge (stored from the
// face of halfedge(e), e as edges() lists it, to the other face): side c of
// face f runs from faces[f][c] to faces[f][(c+1)%3], and its jump is the one
// from f.
template <typename TriangleMesh, typename EdgeMatchingMap, typename VertexIndexMap, typename FaceIndexMap>
void copy_face_matching(const TriangleMesh& tmesh, EdgeMatchingMap matching, VertexIndexMap vim, FaceIndexMap fim,
                        Direction_field_data& data)
{
  data.face_matching.assign(data.faces.size(), {0, 0, 0});
  auto side = [&](auto h) -> int& {
    const std::size_t f = static_cast<std::size_t>(get(fim, face(h, tmesh)));
    const std::size_t first = static_cast<std::size_t>(get(vim, source(h, tmesh)));
    const auto& t = data.faces[f];
    return data.face_matching[f][t[0] == first ? 0 : t[1] == first ? 1 : 2];
  };
  for(auto e : edges(tmesh))
  {
    const auto h = halfedge(e, tmesh);
    if(is_border_edge(h, tmesh)) continue;
    const int jump = static_cast<int>(get(matching, e));
    side(h) = jump;
    side(opposite(h, tmesh)) = -jump;
  }
}

// Whether the data holds a field on faces (make_face_direction_field_data(),
// a .rosy file): directions per face and none per vertex.
inline bool holds_field_on_faces(const Direction_field_data& data)
{
  return data.directions.empty() && !data.faces.empty() && data.face_directions.size() == data.faces.size();
}

} // namespace internal

inline std::vector<std::array<double, 3> > face_directions(const Direction_field_data& data);

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

collects a direction field computed on `tmesh` into a `Direction_field_data`:
the points and triangles of the mesh (in the order of its vertex and face
indices), all `n` directions of each vertex, the magnitudes if a
`vertex_magnitude_map` is given, the per-face directions (see
`face_directions()`) and the singularities with their barycentres.

The `n` directions of vertex `v` are `d` and its rotations by
\f$ 2\pi k / n \f$ about the unit normal made orthogonal to `d`
(`vertex_normal_map`, by default the normalized sum of the incident face
normals weighted by their corner angles, as used by
`compute_globally_optimal_directions()`).

\tparam TriangleMesh a model of `FaceListGraph`
\tparam VertexDirectionMap a `ReadablePropertyMap` from vertices to a 3D vector type with `x()`, `y()`, `z()`
\tparam SingularityRange a range of `std::pair<face_descriptor, int>`, as given by `singularities_output_iterator`

\param tmesh the mesh
\param direction_map the first direction of each vertex
\param degree the degree `n` of the field
\param singularities the singular faces and their integers `k`
\param np optional named parameters: `vertex_point_map`, `vertex_index_map`, `face_index_map`,
       `vertex_normal_map`, `vertex_magnitude_map`
\returns the field as plain arrays
*/
template <typename TriangleMesh, typename VertexDirectionMap, typename SingularityRange,
          typename NamedParameters = parameters::Default_named_parameters>
Direction_field_data make_direction_field_data(const TriangleMesh& tmesh, VertexDirectionMap direction_map, int degree,
                                               const SingularityRange& singularities,
                                               const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  internal::check_degree(degree);
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(tmesh, np);
  const auto fim = CGAL::get_initialized_face_index_map(tmesh, np);

  Direction_field_data data;
  data.degree = degree;
  internal::copy_mesh(tmesh, vpm, vim, fim, data);
  const std::size_t nv = data.points.size();
  std::vector<internal::Vec3> normal;
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::vertex_normal_map_t>::value)
  {
    const auto vnm = get_parameter(np, CGAL::internal_np::vertex_normal_map);
    normal.resize(nv);
    for(auto v : vertices(tmesh)) normal[static_cast<std::size_t>(get(vim, v))] = internal::to_vec3(get(vnm, v));
  }
  else
    normal = internal::angle_weighted_normals(data.points, data.faces);
  std::vector<internal::Vec3> first(nv);
  for(auto v : vertices(tmesh)) first[static_cast<std::size_t>(get(vim, v))] = internal::to_vec3(get(direction_map, v));
  internal::complete_directions(data, normal, first);
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::vertex_magnitude_map_t>::value)
  {
    const auto vmm = get_parameter(np, CGAL::internal_np::vertex_magnitude_map);
    data.magnitudes.resize(nv);
    for(auto v : vertices(tmesh)) data.magnitudes[static_cast<std::size_t>(get(vim, v))] = CGAL::to_double(get(vmm, v));
  }
  for(const auto& fk : singularities)
  {
    const std::size_t f = static_cast<std::size_t>(get(fim, fk.first));
    data.singularities.emplace_back(f, fk.second);
    data.singularity_points.push_back(internal::barycentre(data.points, data.faces[f]));
  }
  data.face_directions = face_directions(data);
  return data;
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

the same, with the degree `n` taken from the result of the computation
(`result.degree`), so that it is not passed twice.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam VertexDirectionMap a `ReadablePropertyMap` from vertices to a 3D vector type with `x()`, `y()`, `z()`
\tparam SingularityRange a range of `std::pair<face_descriptor, int>`, as given by `singularities_output_iterator`

\param tmesh the mesh
\param direction_map the first direction of each vertex
\param result what `compute_globally_optimal_directions()` (or `Globally_optimal_direction_field::compute()`) returned
\param singularities the singular faces and their integers `k`
\param np optional named parameters, as above
\returns the field as plain arrays
*/
template <typename TriangleMesh, typename VertexDirectionMap, typename SingularityRange,
          typename NamedParameters = parameters::Default_named_parameters>
Direction_field_data make_direction_field_data(const TriangleMesh& tmesh, VertexDirectionMap direction_map,
                                               const Direction_field_result& result,
                                               const SingularityRange& singularities,
                                               const NamedParameters& np = parameters::default_values())
{
  return make_direction_field_data(tmesh, direction_map, result.degree, singularities, np);
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

collects a field computed on the faces of `tmesh`
(`compute_globally_optimal_face_directions()`) into a `Direction_field_data`:
the points and triangles of the mesh (in the order of its vertex and face
indices), one direction per face (`face_directions`; the others are its
rotations by \f$ 2\pi k / n \f$ about the face normal), the singular vertices
with their integers `k` (`vertex_singularities`) and, if an
`edge_matching_map` is given, the matching per face side (`face_matching`).
The per-vertex members stay empty: the data holds a field on faces, which the
writers of VTK files, the pictures and the field lines recognise.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam FaceDirectionMap a `ReadablePropertyMap` from faces to a 3D vector type with `x()`, `y()`, `z()`
\tparam SingularityRange a range of `std::pair<vertex_descriptor, int>`, as given by the face field's
         `singularities_output_iterator`

\param tmesh the mesh
\param direction_map the first direction of each face
\param result what `compute_globally_optimal_face_directions()` returned (its degree is used)
\param singular_vertices the singular vertices and their integers `k`
\param np optional named parameters: `vertex_point_map`, `vertex_index_map`, `face_index_map`,
       `edge_matching_map` (the period jump of each edge, as the face field's named parameter of that name)
\returns the field as plain arrays
*/
template <typename TriangleMesh, typename FaceDirectionMap, typename SingularityRange,
          typename NamedParameters = parameters::Default_named_parameters>
Direction_field_data make_face_direction_field_data(const TriangleMesh& tmesh, FaceDirectionMap direction_map,
                                                    const Face_direction_field_result& result,
                                                    const SingularityRange& singular_vertices,
                                                    const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  internal::check_degree(result.degree);
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(tmesh, np);
  const auto fim = CGAL::get_initialized_face_index_map(tmesh, np);
  Direction_field_data data;
  data.degree = result.degree;
  internal::copy_mesh(tmesh, vpm, vim, fim, data);
  data.face_directions.resize(data.faces.size());
  for(auto f : faces(tmesh))
    data.face_directions[static_cast<std::size_t>(get(fim, f))] = internal::to_vec3(get(direction_map, f));
  for(const auto& vk : singular_vertices)
    data.vertex_singularities.emplace_back(static_cast<std::size_t>(get(vim, vk.first)), vk.second);
  if constexpr(!parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_matching_map_t>::value)
    internal::copy_face_matching(tmesh, get_parameter(np, CGAL::internal_np::edge_matching_map), vim, fim, data);
  return data;
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

transfers the field from the vertices to the faces (for the per-face formats
of quad-meshing pipelines). The rule: in the plane of face `f`, with angles
measured from its first edge, each of its three vertices contributes the
unit complex number \f$ e^{\mathrm{i} n \varphi_v} \f$, where \f$ \varphi_v \f$ is
the angle of its first direction projected onto the plane; the face's
direction is at angle \f$ \arg(\sum_v e^{\mathrm{i} n \varphi_v}) / n \f$. Taking
`n`-th powers makes the rule independent of which of its `n` directions a
vertex lists first, so no matching is needed; each vertex's direction is
first turned from its tangent plane onto the face plane by the smallest
rotation taking its normal (`data.normals`) to the face normal, so that the
rule is exactly invariant under the rotations of a vertex's directions. In a singular face the three
powers nearly cancel and the face's direction is not meaningful.

\param data the field with its mesh (`points`, `faces`, `directions`, `normals`)
\returns one unit direction per face, in the face plane
*/
inline std::vector<std::array<double, 3> > face_directions(const Direction_field_data& data)
{
  using internal::Vec3;
  using internal::operator-;
  if(const int e = internal::extreme_scale_exponent(data.points, internal::extreme_coordinate_exponent))
  {
    Direction_field_data scaled = data;
    scaled.points = internal::scaled_by_power_of_two(data.points, -e);
    return face_directions(scaled);
  }
  std::vector<Vec3> result(data.faces.size(), Vec3{0., 0., 0.});
  const int n = data.degree;
  const bool has_normals = data.normals.size() == data.points.size();
  for(std::size_t f = 0; f < data.faces.size(); ++f)
  {
    const auto& t = data.faces[f];
    const Vec3 e = internal::normalized(data.points[t[1]] - data.points[t[0]]);
    const Vec3 normal = internal::triangle_unit_normal(data.points, t);
    const Vec3 e_perp = internal::cross(normal, e);
    std::complex<double> sum(0., 0.);
    for(std::size_t v : t)
    {
      if(data.directions[v].empty()) continue;
      // the vertex's tangent plane turned onto the face's plane: rotations
      // about the vertex normal become rotations about the face normal
      const Vec3 d = has_normals ? internal::rotate_onto(data.directions[v][0], data.normals[v], normal)
                                 : data.directions[v][0];
      const double phi = std::atan2(internal::dot(d, e_perp), internal::dot(d, e));
      if(internal::dot(d, d) > 0.) sum += std::polar(1., n * phi);
    }
    const double angle = std::arg(sum) / n;
    result[f] = Vec3{std::cos(angle) * e[0] + std::sin(angle) * e_perp[0],
                     std::cos(angle) * e[1] + std::sin(angle) * e_perp[1],
                     std::cos(angle) * e[2] + std::sin(angle) * e_perp[2]};
  }
  return result;
}

namespace IO {
// The names under which these were first published (before the plain data had
// its own header): kept so that existing code compiles unchanged.
using Surface_mesh_direction_fields::Direction_field_data;
using Surface_mesh_direction_fields::face_directions;
using Surface_mesh_direction_fields::make_direction_field_data;
} // namespace IO

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_DIRECTION_FIELD_DATA_H
