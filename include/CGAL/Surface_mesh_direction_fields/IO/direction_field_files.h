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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_DIRECTION_FIELD_FILES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_DIRECTION_FIELD_FILES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace IO {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

A direction field on a triangle mesh as stored in, or read from, the files of
this package: plain arrays, independent of the mesh class, so that a file can be
read back and compared without building a mesh.
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
};

inline std::vector<std::array<double, 3> > face_directions(const Direction_field_data& data);

namespace internal {

typedef std::array<double, 3> V3;
inline V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot3(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline V3 cross3(const V3& a, const V3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline V3 scaled(const V3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline V3 unit(const V3& a)
{
  const double l = std::sqrt(dot3(a, a));
  return l > 0. ? scaled(a, 1. / l) : V3{0., 0., 0.};
}

// d rotated by angle about the unit axis n (d orthogonal to n).
inline V3 rotated(const V3& d, const V3& n, double angle)
{
  const V3 nd = cross3(n, d);
  return {std::cos(angle) * d[0] + std::sin(angle) * nd[0], std::cos(angle) * d[1] + std::sin(angle) * nd[1],
          std::cos(angle) * d[2] + std::sin(angle) * nd[2]};
}

typedef std::array<std::size_t, 3> Triangle;

inline V3 barycentre(const std::vector<V3>& points, const Triangle& t)
{
  V3 b{0., 0., 0.};
  for(std::size_t c : t) for(int i = 0; i < 3; ++i) b[i] += points[c][i] / 3.;
  return b;
}

// The unit normal of a counter-clockwise triangle.
inline V3 face_unit_normal(const std::vector<V3>& points, const Triangle& t)
{
  return unit(cross3(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]])));
}

// The minimal rotation taking the unit vector a to the unit vector b, applied to v.
inline V3 rotate_onto(const V3& v, const V3& a, const V3& b)
{
  const V3 axis = cross3(a, b);
  const double s = std::sqrt(dot3(axis, axis)), c = dot3(a, b);
  if(s < 1e-15) return v;  // a = b (or a fold, a = -b: no meaningful rotation)
  const V3 k = scaled(axis, 1. / s);
  const V3 kv = cross3(k, v);
  const double kd = dot3(k, v) * (1. - c);
  return {v[0] * c + kv[0] * s + k[0] * kd, v[1] * c + kv[1] * s + k[1] * kd, v[2] * c + kv[2] * s + k[2] * kd};
}

// Vertex normals: the incident face normals weighted by their corner angles
// (the normals of compute_globally_optimal_directions()).
inline std::vector<V3> angle_weighted_normals(const std::vector<V3>& points,
                                              const std::vector<std::array<std::size_t, 3> >& faces)
{
  std::vector<V3> normal(points.size(), V3{0., 0., 0.});
  for(const auto& t : faces)
  {
    const V3 n = face_unit_normal(points, t);
    for(int c = 0; c < 3; ++c)
    {
      const V3 a = sub(points[t[(c + 1) % 3]], points[t[c]]);
      const V3 b = sub(points[t[(c + 2) % 3]], points[t[c]]);
      const double angle = std::atan2(std::sqrt(dot3(cross3(a, b), cross3(a, b))), dot3(a, b));
      for(int i = 0; i < 3; ++i) normal[t[c]][i] += angle * n[i];
    }
  }
  for(V3& n : normal) n = unit(n);
  return normal;
}

// Normals made orthogonal to each vertex's first direction, and the n
// directions as rotations of the first one about them.
inline void complete_directions(Direction_field_data& data, std::vector<V3> normal, const std::vector<V3>& first)
{
  const std::size_t nv = first.size();
  data.normals.resize(nv);
  data.directions.assign(nv, std::vector<V3>(static_cast<std::size_t>(data.degree)));
  for(std::size_t v = 0; v < nv; ++v)
  {
    const V3 n = unit(sub(normal[v], scaled(first[v], dot3(normal[v], first[v]))));
    data.normals[v] = n;
    for(int k = 0; k < data.degree; ++k)
      data.directions[v][static_cast<std::size_t>(k)] = rotated(first[v], n, 2. * CGAL_PI * k / data.degree);
  }
}

inline void check_degree(int degree)
{
  if(degree < 1)
    throw Invalid_input_error("the degree n must be at least 1 (got " + std::to_string(degree) + ")");
}

// Reads the next token, or throws with the file kind in the message.
inline std::string next_token(std::istream& is, const char* kind)
{
  std::string t;
  if(!(is >> t)) throw Invalid_input_error(std::string("truncated ") + kind + " file");
  return t;
}

// A number from a whole string, or Invalid_input_error.
template <typename T>
T parse_value(const std::string& t, const char* kind)
{
  std::istringstream ts(t);
  T value;
  if(!(ts >> value) || !ts.eof())
    throw Invalid_input_error(std::string("unexpected '") + t + "' in " + kind + " file");
  return value;
}

template <typename T>
T next_value(std::istream& is, const char* kind)
{
  const std::string t = next_token(is, kind);
  std::istringstream ts(t);
  T value;
  if(!(ts >> value) || !ts.eof())
    throw Invalid_input_error(std::string("unexpected '") + t + "' in " + kind + " file");
  return value;
}

inline void expect(std::istream& is, const std::string& word, const char* kind)
{
  const std::string t = next_token(is, kind);
  if(t != word)
    throw Invalid_input_error(std::string(kind) + " file: expected '" + word + "', found '" + t + "'");
}

} // namespace internal

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
  using namespace internal;
  internal::check_degree(degree);
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(tmesh, np);
  const auto fim = CGAL::get_initialized_face_index_map(tmesh, np);
  auto to_v3 = [](const auto& p) {
    return V3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };

  Direction_field_data data;
  data.degree = degree;
  const std::size_t nv = static_cast<std::size_t>(num_vertices(tmesh));
  data.points.resize(nv);
  for(auto v : vertices(tmesh)) data.points[static_cast<std::size_t>(get(vim, v))] = to_v3(get(vpm, v));
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

  // normals: given, or angle-weighted face normals
  std::vector<V3> normal;
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::vertex_normal_map_t>::value)
  {
    const auto vnm = get_parameter(np, CGAL::internal_np::vertex_normal_map);
    normal.resize(nv);
    for(auto v : vertices(tmesh)) normal[static_cast<std::size_t>(get(vim, v))] = to_v3(get(vnm, v));
  }
  else
    normal = angle_weighted_normals(data.points, data.faces);
  std::vector<V3> first(nv);
  for(auto v : vertices(tmesh)) first[static_cast<std::size_t>(get(vim, v))] = to_v3(get(direction_map, v));
  complete_directions(data, normal, first);
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
    data.singularity_points.push_back(barycentre(data.points, data.faces[f]));
  }
  data.face_directions = face_directions(data);
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
  using namespace internal;
  std::vector<V3> result(data.faces.size(), V3{0., 0., 0.});
  const int n = data.degree;
  const bool has_normals = data.normals.size() == data.points.size();
  for(std::size_t f = 0; f < data.faces.size(); ++f)
  {
    const auto& t = data.faces[f];
    const V3 e = unit(sub(data.points[t[1]], data.points[t[0]]));
    const V3 normal = face_unit_normal(data.points, t);
    const V3 e_perp = cross3(normal, e);
    std::complex<double> sum(0., 0.);
    for(std::size_t v : t)
    {
      if(data.directions[v].empty()) continue;
      // the vertex's tangent plane turned onto the face's plane: rotations
      // about the vertex normal become rotations about the face normal
      const V3 d = has_normals ? rotate_onto(data.directions[v][0], data.normals[v], normal) : data.directions[v][0];
      const double phi = std::atan2(dot3(d, e_perp), dot3(d, e));
      if(dot3(d, d) > 0.) sum += std::polar(1., n * phi);
    }
    const double angle = std::arg(sum) / n;
    result[f] = V3{std::cos(angle) * e[0] + std::sin(angle) * e_perp[0],
                   std::cos(angle) * e[1] + std::sin(angle) * e_perp[1],
                   std::cos(angle) * e[2] + std::sin(angle) * e_perp[2]};
  }
  return result;
}

/// \name VTK
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the field as a legacy VTK PolyData file (ASCII), which ParaView and
VTK open: the triangles (`POLYGONS`), then the barycentres of the singular
faces as extra points with one `VERTICES` cell each; point data
`direction_0` ... `direction_{n-1}` (`VECTORS`, zero on the extra points) and
`magnitude` (if known); cell data `singularity_index` (the index `k / n` on
the singularity cells, 0 on the triangles). Coordinates are written with 17
significant digits, so that reading back gives the same doubles.

\param os the output stream
\param data the field to write
*/
inline void write_VTK(std::ostream& os, const Direction_field_data& data)
{
  const std::size_t nv = data.points.size(), ns = data.singularities.size(), nf = data.faces.size();
  os << std::setprecision(17);
  os << "# vtk DataFile Version 3.0\n"
     << "direction field of degree " << data.degree << " (CGAL Surface_mesh_direction_fields)\n"
     << "ASCII\nDATASET POLYDATA\n";
  os << "POINTS " << nv + ns << " double\n";
  for(const auto& p : data.points) os << p[0] << " " << p[1] << " " << p[2] << "\n";
  for(const auto& p : data.singularity_points) os << p[0] << " " << p[1] << " " << p[2] << "\n";
  if(ns > 0)
  {
    os << "VERTICES " << ns << " " << 2 * ns << "\n";
    for(std::size_t i = 0; i < ns; ++i) os << "1 " << nv + i << "\n";
  }
  os << "POLYGONS " << nf << " " << 4 * nf << "\n";
  for(const auto& t : data.faces) os << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  os << "POINT_DATA " << nv + ns << "\n";
  for(int k = 0; k < data.degree; ++k)
  {
    os << "VECTORS direction_" << k << " double\n";
    for(std::size_t v = 0; v < nv; ++v)
    {
      const auto& d = data.directions[v][static_cast<std::size_t>(k)];
      os << d[0] << " " << d[1] << " " << d[2] << "\n";
    }
    for(std::size_t i = 0; i < ns; ++i) os << "0 0 0\n";
  }
  if(!data.magnitudes.empty())
  {
    os << "SCALARS magnitude double 1\nLOOKUP_TABLE default\n";
    for(double m : data.magnitudes) os << m << "\n";
    for(std::size_t i = 0; i < ns; ++i) os << "0\n";
  }
  // cells are ordered vertices first, then polygons
  os << "CELL_DATA " << ns + nf << "\nSCALARS singularity_index double 1\nLOOKUP_TABLE default\n";
  for(const auto& s : data.singularities) os << static_cast<double>(s.second) / data.degree << "\n";
  for(std::size_t f = 0; f < nf; ++f) os << "0\n";
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a file written by `write_VTK()` back. The singular faces are recovered
by matching each singularity point to the barycentre of a face (they are
written from it); the per-face directions are recomputed by
`face_directions()`.

\throws Invalid_input_error if the stream is not such a file
\param is the input stream
\returns the field read
*/
inline Direction_field_data read_VTK(std::istream& is)
{
  using namespace internal;
  const char* kind = "VTK";
  Direction_field_data data;
  std::string line;
  std::getline(is, line);
  if(line.rfind("# vtk DataFile", 0) != 0) throw Invalid_input_error("not a legacy VTK file");
  std::getline(is, line);
  const std::string key = "direction field of degree ";
  if(line.rfind(key, 0) != 0) throw Invalid_input_error("VTK file: not written by write_VTK()");
  {
    std::istringstream ls(line.substr(key.size()));
    std::string word;
    ls >> word;
    data.degree = parse_value<int>(word, kind);
  }
  check_degree(data.degree);
  expect(is, "ASCII", kind);
  expect(is, "DATASET", kind);
  expect(is, "POLYDATA", kind);
  expect(is, "POINTS", kind);
  const std::size_t np = next_value<std::size_t>(is, kind);
  if(np > (std::size_t(1) << 32)) throw Invalid_input_error("VTK file: implausible number of points");
  next_token(is, kind);  // type
  std::vector<V3> points(np);
  for(auto& p : points) for(double& x : p) x = next_value<double>(is, kind);
  std::size_t ns = 0, nf = 0;
  std::string word = next_token(is, kind);
  if(word == "VERTICES")
  {
    ns = next_value<std::size_t>(is, kind);
    next_value<std::size_t>(is, kind);
    for(std::size_t i = 0; i < 2 * ns; ++i) next_value<std::size_t>(is, kind);
    word = next_token(is, kind);
  }
  if(word != "POLYGONS") throw Invalid_input_error("VTK file: expected POLYGONS");
  nf = next_value<std::size_t>(is, kind);
  next_value<std::size_t>(is, kind);
  if(ns > np) throw Invalid_input_error("VTK file: more singularities than points");
  const std::size_t nv = np - ns;
  data.points.assign(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(nv));
  data.singularity_points.assign(points.begin() + static_cast<std::ptrdiff_t>(nv), points.end());
  data.faces.resize(nf);
  for(auto& t : data.faces)
  {
    if(next_value<int>(is, kind) != 3) throw Invalid_input_error("VTK file: a polygon is not a triangle");
    for(auto& c : t)
    {
      c = next_value<std::size_t>(is, kind);
      if(c >= nv) throw Invalid_input_error("VTK file: a vertex index is out of range");
    }
  }
  expect(is, "POINT_DATA", kind);
  next_value<std::size_t>(is, kind);
  data.directions.assign(nv, std::vector<V3>(static_cast<std::size_t>(data.degree)));
  std::vector<double> singularity_values;
  while(is >> word)
  {
    if(word == "VECTORS")
    {
      const std::string name = next_token(is, kind);
      next_token(is, kind);
      const int k = parse_value<int>(name.substr(name.find('_') + 1), kind);
      if(k < 0 || k >= data.degree) throw Invalid_input_error("VTK file: unexpected " + name);
      for(std::size_t v = 0; v < np; ++v)
      {
        V3 d;
        for(double& x : d) x = next_value<double>(is, kind);
        if(v < nv) data.directions[v][static_cast<std::size_t>(k)] = d;
      }
    }
    else if(word == "SCALARS")
    {
      const std::string name = next_token(is, kind);
      next_token(is, kind);
      next_token(is, kind);
      expect(is, "LOOKUP_TABLE", kind);
      next_token(is, kind);
      if(name == "magnitude")
      {
        data.magnitudes.resize(nv);
        for(std::size_t v = 0; v < np; ++v)
        {
          const double m = next_value<double>(is, kind);
          if(v < nv) data.magnitudes[v] = m;
        }
      }
      else if(name == "singularity_index")
      {
        for(std::size_t c = 0; c < ns + nf; ++c)
        {
          const double value = next_value<double>(is, kind);
          if(c < ns) singularity_values.push_back(value);
        }
      }
      else throw Invalid_input_error("VTK file: unexpected data " + name);
    }
    else if(word == "CELL_DATA")
      next_value<std::size_t>(is, kind);
    else
      throw Invalid_input_error("VTK file: unexpected '" + word + "'");
  }
  // the normals (not stored in the file): angle-weighted, orthogonal to d_0
  const std::vector<V3> normal = angle_weighted_normals(data.points, data.faces);
  data.normals.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const V3& d = data.directions[v][0];
    data.normals[v] = unit(sub(normal[v], scaled(d, dot3(normal[v], d))));
  }
  // singular faces: the face whose barycentre is the singularity point
  std::vector<V3> centres;
  if(ns > 0)
    for(const auto& t : data.faces) centres.push_back(barycentre(data.points, t));
  for(std::size_t i = 0; i < ns; ++i)
  {
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < nf; ++f)
    {
      const V3 d = sub(centres[f], data.singularity_points[i]);
      if(dot3(d, d) < best_distance) { best_distance = dot3(d, d); best = f; }
    }
    if(i >= singularity_values.size()) throw Invalid_input_error("VTK file: no singularity_index for a singularity point");
    data.singularities.emplace_back(best, static_cast<int>(std::lround(singularity_values[i] * data.degree)));
  }
  data.face_directions = face_directions(data);
  return data;
}

/// @}

/// \name PLY
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the field as an ASCII PLY file: per vertex `x y z`, the first
direction `dx dy dz`, and `magnitude` (if known); per face its
`vertex_indices` and `singularity` (the integer `k` of its index `k / n`).
The degree is in the comment `direction_field_degree n`. Readers that do not
know the extra properties (e.g. `CGAL::IO::read_PLY()` into a
`Surface_mesh`, which keeps them as property maps `v:dx`, ...) still read the mesh.

\param os the output stream
\param data the field to write
*/
inline void write_PLY(std::ostream& os, const Direction_field_data& data)
{
  const bool has_magnitude = !data.magnitudes.empty();
  std::vector<int> singularity(data.faces.size(), 0);
  for(const auto& s : data.singularities) singularity[s.first] = s.second;
  os << std::setprecision(17);
  os << "ply\nformat ascii 1.0\ncomment CGAL Surface_mesh_direction_fields\n"
     << "comment direction_field_degree " << data.degree << "\n"
     << "element vertex " << data.points.size() << "\n"
     << "property double x\nproperty double y\nproperty double z\n"
     << "property double dx\nproperty double dy\nproperty double dz\n";
  if(has_magnitude) os << "property double magnitude\n";
  os << "element face " << data.faces.size() << "\n"
     << "property list uchar int vertex_indices\nproperty int singularity\nend_header\n";
  for(std::size_t v = 0; v < data.points.size(); ++v)
  {
    const auto& p = data.points[v];
    const auto& d = data.directions[v][0];
    os << p[0] << " " << p[1] << " " << p[2] << " " << d[0] << " " << d[1] << " " << d[2];
    if(has_magnitude) os << " " << data.magnitudes[v];
    os << "\n";
  }
  for(std::size_t f = 0; f < data.faces.size(); ++f)
    os << "3 " << data.faces[f][0] << " " << data.faces[f][1] << " " << data.faces[f][2] << " " << singularity[f]
       << "\n";
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a file written by `write_PLY()` back; the `n` directions of each vertex
are rebuilt from the first one by rotation about the angle-weighted vertex
normal of the file's mesh (as `make_direction_field_data()` does).

\throws Invalid_input_error if the stream is not such a file
\param is the input stream
\returns the field read
*/
inline Direction_field_data read_PLY(std::istream& is)
{
  using namespace internal;
  const char* kind = "PLY";
  Direction_field_data data;
  std::string line;
  std::size_t nv = 0, nf = 0;
  bool has_magnitude = false, degree_found = false;
  if(!std::getline(is, line) || line.rfind("ply", 0) != 0) throw Invalid_input_error("not a PLY file");
  while(std::getline(is, line))
  {
    std::istringstream ls(line);
    std::string a, b, c;
    ls >> a >> b >> c;
    if(a == "format" && b != "ascii") throw Invalid_input_error("PLY file: only ASCII is read");
    if(a == "comment" && b == "direction_field_degree") { data.degree = parse_value<int>(c, kind); degree_found = true; }
    if(a == "element" && b == "vertex") nv = parse_value<std::size_t>(c, kind);
    if(a == "element" && b == "face") nf = parse_value<std::size_t>(c, kind);
    if(a == "property" && c == "magnitude") has_magnitude = true;
    if(a == "end_header") break;
  }
  if(!degree_found) throw Invalid_input_error("PLY file: no 'comment direction_field_degree'");
  if(nv > (std::size_t(1) << 32) || nf > (std::size_t(1) << 32))
    throw Invalid_input_error("PLY file: implausible element count");
  check_degree(data.degree);
  data.points.resize(nv);
  std::vector<V3> first(nv);
  if(has_magnitude) data.magnitudes.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
  {
    for(double& x : data.points[v]) x = next_value<double>(is, kind);
    for(double& x : first[v]) x = next_value<double>(is, kind);
    if(has_magnitude) data.magnitudes[v] = next_value<double>(is, kind);
  }
  data.faces.resize(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(next_value<int>(is, kind) != 3) throw Invalid_input_error("PLY file: a face is not a triangle");
    for(auto& c : data.faces[f])
    {
      c = next_value<std::size_t>(is, kind);
      if(c >= nv) throw Invalid_input_error("PLY file: a vertex index is out of range");
    }
    const int k = next_value<int>(is, kind);
    if(k != 0)
    {
      data.singularities.emplace_back(f, k);
      data.singularity_points.push_back(barycentre(data.points, data.faces[f]));
    }
  }
  // the other directions: rotations about the angle-weighted normal
  complete_directions(data, angle_weighted_normals(data.points, data.faces), first);
  data.face_directions = face_directions(data);
  return data;
}

/// @}

/// \name Per-face formats for quad meshing
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the per-face field (`data.face_directions`) as a `.rosy` file as read by
vcglib's `ImporterFIELD::Load4ROSY()` (and QuadWild): the number of faces,
the degree `n`, then one direction `x y z` per face. vcglib reads `n = 4` only.

\param os the output stream
\param data the field to write
*/
inline void write_rosy(std::ostream& os, const Direction_field_data& data)
{
  os << std::setprecision(17);
  os << data.faces.size() << "\n" << data.degree << "\n";
  for(const auto& d : data.face_directions) os << d[0] << " " << d[1] << " " << d[2] << "\n";
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a `.rosy` file: sets `degree` and `face_directions` of `data` (whose
mesh must have as many faces as the file).

\throws Invalid_input_error if the file does not match
\param is the input stream
\param data receives what the file holds
*/
inline void read_rosy(std::istream& is, Direction_field_data& data)
{
  using namespace internal;
  const std::size_t nf = next_value<std::size_t>(is, "rosy");
  if(!data.faces.empty() && nf != data.faces.size())
    throw Invalid_input_error("rosy file: " + std::to_string(nf) + " faces for a mesh of " +
                              std::to_string(data.faces.size()));
  if(nf > (std::size_t(1) << 32)) throw Invalid_input_error("rosy file: implausible face count");
  data.degree = next_value<int>(is, "rosy");
  check_degree(data.degree);
  data.face_directions.resize(nf);
  for(auto& d : data.face_directions) for(double& x : d) x = next_value<double>(is, "rosy");
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the per-face field as an `.ffield` file as read by vcglib's
`ImporterFIELD::LoadFFIELD()` (a cross per face, given by two orthogonal
unit vectors): a comment line, `target frame`, the number of faces, a header
line, then per face `1 1` and the two vectors: the face's direction and its
rotation by \f$ 90^\circ \f$ in the face plane. This describes the field exactly for
`n = 4` (and the line or vector field's cross otherwise).

\param os the output stream
\param data the field to write
*/
inline void write_ffield(std::ostream& os, const Direction_field_data& data)
{
  using namespace internal;
  os << std::setprecision(17);
  os << "# frame generated by CGAL Surface_mesh_direction_fields, degree " << data.degree << "\n"
     << "target frame\n" << data.faces.size() << "\n"
     << "k1 k2 k1v_x k1v_y k1v_z k2v_x k2v_y k2v_z\n";
  for(std::size_t f = 0; f < data.faces.size(); ++f)
  {
    const auto& t = data.faces[f];
    const V3 normal = face_unit_normal(data.points, t);
    const V3& u = data.face_directions[f];
    const V3 w = cross3(normal, u);
    os << "1 1 " << u[0] << " " << u[1] << " " << u[2] << " " << w[0] << " " << w[1] << " " << w[2] << "\n";
  }
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads an `.ffield` file: sets `face_directions` of `data` to the first vector
of each face (normalized).

\throws Invalid_input_error if the file does not match
\param is the input stream
\param data receives what the file holds
*/
inline void read_ffield(std::istream& is, Direction_field_data& data)
{
  using namespace internal;
  std::string line;
  if(!std::getline(is, line) || line.empty() || line[0] != '#') throw Invalid_input_error("not an ffield file");
  std::getline(is, line);  // "target frame"
  const std::size_t nf = next_value<std::size_t>(is, "ffield");
  if(nf > (std::size_t(1) << 32)) throw Invalid_input_error("ffield file: implausible face count");
  if(!data.faces.empty() && nf != data.faces.size())
    throw Invalid_input_error("ffield file: " + std::to_string(nf) + " faces for a mesh of " +
                              std::to_string(data.faces.size()));
  std::getline(is, line);
  std::getline(is, line);  // the header line
  data.face_directions.resize(nf);
  for(auto& d : data.face_directions)
  {
    next_value<double>(is, "ffield");
    next_value<double>(is, "ffield");
    for(double& x : d) x = next_value<double>(is, "ffield");
    for(int i = 0; i < 3; ++i) next_value<double>(is, "ffield");
    d = unit(d);
  }
}

/// @}

/// \name Singularities
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the singularities as text: a comment line, then one line per singular
face: `face k n x y z` (its index is `k / n`; `x y z` is its barycentre).

\param os the output stream
\param data the field to write
*/
inline void write_singularities(std::ostream& os, const Direction_field_data& data)
{
  os << std::setprecision(17);
  os << "# face k n x y z   (index k/n at the barycentre x y z)\n";
  for(std::size_t i = 0; i < data.singularities.size(); ++i)
  {
    const auto& p = data.singularity_points[i];
    os << data.singularities[i].first << " " << data.singularities[i].second << " " << data.degree << " " << p[0]
       << " " << p[1] << " " << p[2] << "\n";
  }
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a file written by `write_singularities()`: sets `singularities`,
`singularity_points` and `degree` of `data`.

\throws Invalid_input_error on a malformed line
\param is the input stream
\param data receives what the file holds
*/
inline void read_singularities(std::istream& is, Direction_field_data& data)
{
  data.singularities.clear();
  data.singularity_points.clear();
  std::string line;
  std::size_t number = 0;
  while(std::getline(is, line))
  {
    ++number;
    if(line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::size_t f;
    int k, n;
    std::array<double, 3> p;
    if(!(ls >> f >> k >> n >> p[0] >> p[1] >> p[2]))
      throw Invalid_input_error("singularities file: line " + std::to_string(number) + " is malformed");
    data.degree = n;
    data.singularities.emplace_back(f, k);
    data.singularity_points.push_back(p);
  }
}

/// @}

} // namespace IO
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_DIRECTION_FIELD_FILES_H
