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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_POINT_SET_DIRECTIONS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_POINT_SET_DIRECTIONS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Globally_optimal_direction_field.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/named_inputs.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/point_set_field.h>

#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD)
#  include <CGAL/Surface_mesh_direction_fields/Cholmod_supernodal_solver.h>
#endif

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

What `compute_globally_optimal_point_set_directions()` found besides the
directions. Points are numbered in the order of the range; triangles list three
point numbers, counter-clockwise about the points' normals.
*/
struct Point_set_direction_field_result
{
  /// the normal used at each point (given, or estimated), of unit length
  std::vector<std::array<double, 3> > normals;
  /// whether the normals were estimated (no `normal_map` given)
  bool normals_estimated = false;
  /// the magnitude of the field at each point, relative to its largest in the point's component (1 there; the
  /// directions are less certain where it is small, as on a mesh)
  std::vector<double> magnitudes;
  /// the triangles of the local triangulations, each once
  std::vector<std::array<std::size_t, 3> > triangles;
  /// for each triangle, how many of its three points' local triangulations hold it (1 to 3)
  std::vector<unsigned char> holders;
  /// for each triangle, whether it belongs to the surface the singularities are read on: the triangles taken
  /// by decreasing holders, each unless one of its sides, in its direction, belongs to one taken before
  std::vector<unsigned char> on_surface;
  /// the surface triangles around which the field turns, with their integer index `k` (the index is `k / n`)
  std::vector<std::pair<std::size_t, int> > singular_triangles;
  /// per connected component (points joined by triangles), as on a mesh
  std::vector<Component_report> components;
  /// the points in no triangle: they receive the zero vector
  std::size_t number_of_points_without_triangles = 0;
  /// the Euler characteristic V - E + F of the surface triangles; where the surface closes, the indices of
  /// `singular_triangles` add up to `n` times it (the user manual says when they may not elsewhere)
  int surface_euler_characteristic = 0;
  /// whether every side of a surface triangle is a side of another one
  bool surface_is_closed = false;
  /// where the time went: `setup_ms` holds the neighbours, the local triangulations and the assembly
  Direction_field_timings timings;
  /// of `timings.setup_ms`, the estimation of the normals (0 when they are given)
  double normals_ms = 0.;
};

namespace internal {

template <typename PointRange, typename PointMap>
std::vector<Vec3> point_positions(const PointRange& points, PointMap point_map)
{
  std::vector<Vec3> positions;
  for(const auto& p : points)
  {
    const auto& q = get(point_map, p);
    positions.push_back({to_double(q.x()), to_double(q.y()), to_double(q.z())});
    for(double x : positions.back())
      if(!std::isfinite(x))
        throw Invalid_input_error("point " + std::to_string(positions.size() - 1) + " has a coordinate that is not finite");
  }
  return positions;
}

// Unit normals by CGAL's jet fitting over k neighbours, oriented by its
// minimum spanning tree; a normal that the tree leaves unoriented is kept as
// fitted.
inline std::vector<Vec3> estimated_normals(const std::vector<Vec3>& positions, unsigned int k)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
  typedef std::tuple<Kernel::Point_3, Kernel::Vector_3, std::size_t> Sample;
  std::vector<Sample> samples;
  for(std::size_t i = 0; i < positions.size(); ++i)
    samples.emplace_back(Kernel::Point_3(positions[i][0], positions[i][1], positions[i][2]), Kernel::Vector_3(0, 0, 0),
                         i);
  const auto np = CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Sample>())
                    .normal_map(CGAL::Nth_of_tuple_property_map<1, Sample>());
  CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(samples, k, np);
  CGAL::mst_orient_normals(samples, k, np);
  std::vector<Vec3> normals(positions.size());
  for(const Sample& s : samples)
  {
    const Kernel::Vector_3& v = std::get<1>(s);
    normals[std::get<2>(s)] = normalized(Vec3{v.x(), v.y(), v.z()});
  }
  return normals;
}

// Whether the named parameters hold a normal map, and a valid one: the
// maps of `Point_set_3` convert to false where the property is absent, and
// `Point_set_3::parameters()` names its normal map even then.
template <typename NamedParameters>
bool names_normals(const NamedParameters& np)
{
  if constexpr(parameters::is_default_parameter<NamedParameters, internal_np::normal_t>::value)
    return false;
  else
  {
    const auto map = parameters::get_parameter(np, internal_np::normal_map);
    if constexpr(std::is_constructible<bool, decltype(map)>::value) return static_cast<bool>(map);
    else return true;
  }
}

template <typename PointRange, typename NormalMap>
std::vector<Vec3> given_normals(const PointRange& points, NormalMap normal_map)
{
  std::vector<Vec3> normals;
  for(const auto& p : points)
  {
    const auto& v = get(normal_map, p);
    const Vec3 n = {to_double(v.x()), to_double(v.y()), to_double(v.z())};
    if(!(squared_norm(n) > 0.) || !std::isfinite(squared_norm(n)))
      throw Invalid_input_error("the normal of point " + std::to_string(normals.size()) + " is zero or not finite");
    normals.push_back(normalized(n));
  }
  return normals;
}

// The direction of angle phi in the tangent plane of point i.
inline Vec3 point_direction(const Point_set_domain& d, std::size_t i, double phi)
{
  return std::cos(phi) * d.reference[i] + std::sin(phi) * cross(d.normals[i], d.reference[i]);
}

inline std::vector<double> relative_magnitudes(const Point_set_solution& solution)
{
  std::vector<double> magnitudes(solution.coefficients.size(), 0.);
  for(const Point_set_component& c : solution.components)
  {
    double largest = 0.;
    for(std::size_t p : c.points) largest = (std::max)(largest, std::abs(solution.coefficients[p]));
    if(largest > 0.)
      for(std::size_t p : c.points) magnitudes[p] = std::abs(solution.coefficients[p]) / largest;
  }
  return magnitudes;
}

inline void report_point_set(const Point_set_domain& d, const Point_set_solution& solution,
                             Point_set_direction_field_result& result)
{
  const Indexed_mesh& m = d.triangles;
  const Directed_sides sides = directed_sides(m);
  result.on_surface = surface_triangles(d, sides);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
  {
    result.triangles.push_back({m.faces[f][0], m.faces[f][1], m.faces[f][2]});
    if(solution.face_index[f] != 0 && result.on_surface[f]) result.singular_triangles.push_back({f, solution.face_index[f]});
  }
  result.holders = d.holders;
  std::size_t covered = 0;
  for(const Point_set_component& c : solution.components)
  {
    Component_report report;
    report.number_of_vertices = c.points.size();
    report.number_of_faces = c.faces.size();
    report.eigenvalue = c.eigenvalue;
    report.residual = c.residual;
    report.iterations = c.iterations;
    report.converged = c.converged;
    report.solve = Field_solve::EIGEN_SOLVE;
    result.components.push_back(report);
    covered += c.points.size();
  }
  result.number_of_points_without_triangles = m.number_of_vertices() - covered;
  std::tie(result.surface_euler_characteristic, result.surface_is_closed) = surface_characteristic(d, sides, result.on_surface);
}

} // namespace internal

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

\brief computes the globally smoothest unit `n`-direction field of a point set,
and its singularities.

The points need no mesh: each point's nearest neighbours are projected onto
its tangent plane and triangulated there, and the field is the smoothest one
for the energy and mass of the mesh method summed over these local
triangulations (see the \ref SMDF_point_sets "user manual"). Each connected
component (points joined by triangles) is solved on its own; a point in no
triangle receives the zero vector.

\tparam PointRange a model of `ConstRange` whose iterator type is `InputIterator`
\tparam PointDirectionMap a model of `WritablePropertyMap` with the range's value type as key type and
        `GT::Vector_3` as value type
\tparam NamedParameters a sequence of Named Parameters

\param points the input points; they are not modified
\param direction_map receives one unit direction per point, orthogonal to its normal (the other `n - 1`
       are its rotations by \f$ 2\pi k / n \f$ about the normal)
\param np an optional sequence of Named Parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{the position of each point}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{normal_map}
    \cgalParamDescription{a normal per point (any length but zero); a map that converts to `false`, as
                           `Point_set_3::parameters()` names for a point set without normals, counts as none}
    \cgalParamDefault{estimated: `CGAL::jet_estimate_normals()` over `number_of_neighbors` neighbours, oriented
                      by `CGAL::mst_orient_normals()`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{the traits class}
    \cgalParamDefault{the kernel of the point type}
  \cgalParamNEnd
  \cgalParamNBegin{degree}
    \cgalParamDescription{the number `n` of directions, 1 to `maximum_degree`}
    \cgalParamDefault{`default_degree` (4)}
  \cgalParamNEnd
  \cgalParamNBegin{smoothness_parameter}
    \cgalParamDescription{`s` in \f$[-1, 1]\f$, as on a mesh}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_neighbors}
    \cgalParamDescription{how many nearest points each local triangulation (and each fitted normal) is built
                           from, 3 or more; about 24 for noisy scans, where 12 lets the noise into the tangent planes}
    \cgalParamDefault{`default_number_of_neighbors` (12)}
  \cgalParamNEnd
  \cgalParamNBegin{residual_tolerance}
    \cgalParamDescription{the eigen-solve's relative residual, as on a mesh}
    \cgalParamDefault{`1e-10`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Point_set_direction_field_result`: the normals used, the triangles of the local triangulations and
         the surface triangles, the singular triangles with their indices, and per component the smallest
         eigenvalue, the iterations and the residual

\throws Invalid_input_error with fewer than 3 points, a coordinate or normal that is not finite, an option out
        of range, or no triangle at all (all points on a line, or all at one position)
*/
#ifndef DOXYGEN_RUNNING
inline namespace CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE {  // see Default_direction_field_solver
#endif
template <typename PointRange, typename PointDirectionMap, typename NamedParameters = parameters::Default_named_parameters>
Point_set_direction_field_result compute_globally_optimal_point_set_directions(
  const PointRange& points, PointDirectionMap direction_map, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits GT;

  const int degree = choose_parameter(get_parameter(np, internal_np::degree), default_degree);
  const double s = choose_parameter(get_parameter(np, internal_np::smoothness_parameter), 0.);
  internal::check_field_parameters(degree, s);
  const unsigned int k = internal::checked_count(
    choose_parameter(get_parameter(np, internal_np::number_of_neighbors), default_number_of_neighbors),
    "number_of_neighbors");
  if(k < 3) throw Invalid_input_error("number_of_neighbors must be 3 or more (got " + std::to_string(k) + ")");
  internal::Eigen_solve_options options;
  options.residual_tolerance = choose_parameter(get_parameter(np, internal_np::residual_tolerance), 1e-10);

  internal::Indexed_mesh cloud;
  cloud.points = internal::point_positions(points, NP_helper::get_const_point_map(points, np));
  if(cloud.points.size() < 3)
    throw Invalid_input_error("a point set needs 3 points or more (got " + std::to_string(cloud.points.size()) + ")");
  internal::normalize_coordinates(cloud);  // the field does not change; the arithmetic stays in range

  const auto start = std::chrono::steady_clock::now();
  Point_set_direction_field_result result;
  std::vector<internal::Vec3> normals;
  if(internal::names_normals(np))
    normals = internal::given_normals(points, NP_helper::get_normal_map(points, np));
  else
  {
    normals = internal::estimated_normals(cloud.points, k);
    result.normals_estimated = true;
    result.normals_ms = internal::milliseconds_since(start);
  }
  const internal::Local_triangles local = internal::local_triangulations(cloud.points, normals, k);
  const internal::Point_set_domain domain = internal::make_point_set_domain(cloud.points, normals, local, degree);
  if(domain.triangles.number_of_faces() == 0)
    throw Invalid_input_error("the points span no triangle (all on a line or at one position)");

  Default_direction_field_solver solver;
  const double before_solve = internal::milliseconds_since(start);
  const internal::Point_set_solution solution = internal::solve_point_set_field(domain, s, options, solver);
  internal::report_point_set(domain, solution, result);
  result.timings.factorization_ms = solution.factorization_ms;
  result.timings.setup_ms = before_solve + solution.assembly_ms;
  result.normals = normals;
  result.magnitudes = internal::relative_magnitudes(solution);

  std::size_t i = 0;
  for(const auto& p : points)
  {
    const std::complex<double> u = solution.coefficients[i];
    const internal::Vec3 dir =
      std::abs(u) > 0. ? internal::point_direction(domain, i, std::arg(u) / degree) : internal::Vec3{0., 0., 0.};
    put(direction_map, p, typename GT::Vector_3(dir[0], dir[1], dir[2]));
    ++i;
  }
  result.timings.total_ms = internal::milliseconds_since(start);
  result.timings.solve_ms = result.timings.total_ms - result.timings.setup_ms - result.timings.factorization_ms;
  return result;
}

#ifndef DOXYGEN_RUNNING
} // inline namespace CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE
#endif

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_POINT_SET_DIRECTIONS_H
