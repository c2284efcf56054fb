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
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/progress_report.h>
// the method on the local triangulations behind one seam (Point_set_engine.h)
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Point_set_engine.h>
#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION
#  include <CGAL/Surface_mesh_direction_fields/internal/Engine/Point_set_engine_impl.h>
#  if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD)
#    include <CGAL/Surface_mesh_direction_fields/Cholmod_supernodal_solver.h>
#  endif
#endif

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The map's value at each point (a position or a vector) as three doubles,
// every coordinate finite; `refusal(i)`: the error's words for point i.
template <typename PointRange, typename Map, typename Refusal>
std::vector<Vec3> finite_values(const PointRange& points, Map map, Refusal refusal)
{
  std::vector<Vec3> values;
  for(const auto& p : points)
  {
    const auto& v = get(map, p);
    values.push_back({to_double(v.x()), to_double(v.y()), to_double(v.z())});
    for(double x : values.back())
      if(!std::isfinite(x)) throw Invalid_input_error(refusal(values.size() - 1));
  }
  return values;
}

template <typename PointRange, typename PointMap>
std::vector<Vec3> point_positions(const PointRange& points, PointMap point_map)
{
  return finite_values(points, point_map, [](std::size_t i) {
    return "point " + std::to_string(i) + " has a coordinate that is not finite";
  });
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

// The user's guidance vectors, one per point (any length; zero: no preference).
template <typename PointRange, typename GuidanceMap>
std::vector<Vec3> point_guidance(const PointRange& points, GuidanceMap guidance_map)
{
  return finite_values(points, guidance_map, [](std::size_t i) {
    return "the guidance vector of point " + std::to_string(i) + " is not finite";
  });
}

// The hard constraints: which points are constrained, and the direction of
// each constrained one (finite; the map is read at those points only).
template <typename PointRange, typename ConstrainedMap, typename DirectionMap>
void point_constraints(const PointRange& points, ConstrainedMap is_constrained, DirectionMap direction_map,
                       Point_set_field_request& request)
{
  for(const auto& p : points)
  {
    const bool constrained = get(is_constrained, p);
    request.is_constrained.push_back(constrained ? 1 : 0);
    request.constrained_directions.push_back({0., 0., 0.});
    if(!constrained) continue;
    const auto& d = get(direction_map, p);
    Vec3& direction = request.constrained_directions.back();
    direction = {to_double(d.x()), to_double(d.y()), to_double(d.z())};
    for(double x : direction)
      if(!std::isfinite(x))
        throw Invalid_input_error("the constrained direction of point " +
                                  std::to_string(request.is_constrained.size() - 1) + " is not finite");
  }
}

template <typename PointRange, typename NormalMap>
std::vector<Vec3> given_normals(const PointRange& points, NormalMap normal_map)
{
  const auto refusal = [](std::size_t i) { return "the normal of point " + std::to_string(i) + " is zero or not finite"; };
  std::vector<Vec3> normals = finite_values(points, normal_map, refusal);
  for(std::size_t i = 0; i < normals.size(); ++i)
  {
    if(!(squared_norm(normals[i]) > 0.) || !std::isfinite(squared_norm(normals[i]))) throw Invalid_input_error(refusal(i));
    normals[i] = normalized(normals[i]);
  }
  return normals;
}

} // namespace internal

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

\brief computes the globally smoothest (or guided) unit `n`-direction field of
a point set, and its singularities.

The points need no mesh: each point's nearest neighbours are projected onto
its tangent plane and triangulated there, and the field is the smoothest one
for the energy and mass of the mesh method summed over these local
triangulations (see the \ref SMDF_point_sets "user manual"), or with
`point_guidance_map` or `principal_curvature_alignment` the field that trades
smoothness for alignment with the guidance, as on a mesh. Each connected component (points joined by triangles)
is solved on its own; a point in no triangle receives the zero vector.

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
    \cgalParamDefault{estimated: the normal of a quadric fitted to the point and its `number_of_neighbors` nearest
                      points over their least-squares plane (the jet fit of `CGAL::jet_estimate_normals()`), oriented
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
  \cgalParamNBegin{principal_curvature_alignment}
    \cgalParamDescription{guidance by the principal curvatures (an even `n`), as on a mesh: a quadric is fitted to
                          each point and its `2 * number_of_neighbors` nearest points over its tangent plane (the
                          mesh's quadric fit, on neighbours instead of a two-ring); which curvature is the larger
                          depends on the normals' side (outward: a convex bend is positive)}
    \cgalParamType{`Principal_curvature_alignment`}
    \cgalParamDefault{`Principal_curvature_alignment::NONE`}
  \cgalParamNEnd
  \cgalParamNBegin{point_guidance_map}
    \cgalParamDescription{a guidance vector per point, projected to the point's tangent plane; its length is its
                          weight and the zero vector means no preference (as `vertex_guidance_map` on a mesh; with
                          curvature alignment, a nonzero vector replaces the curvature guidance at its point). The
                          field then solves \f$ (A - \lambda_t M) u = M q \f$ per component, as on a mesh}
    \cgalParamType{a model of `ReadablePropertyMap` with the range's value type as key type and `GT::Vector_3` as
                   value type}
    \cgalParamDefault{no guidance: the smoothest field}
  \cgalParamNEnd
  \cgalParamNBegin{point_is_constrained_map}
    \cgalParamDescription{the points whose direction is fixed (hard constraints, as `vertex_is_constrained_map` on
                          a mesh): with `point_constrained_direction_map`, a direction per constrained point,
                          projected to its tangent plane, which the field takes exactly; the field is then the one
                          that follows the constraints (a linear solve), guided or not}
    \cgalParamType{a model of `ReadablePropertyMap` with the range's value type as key type and `bool` as value type}
    \cgalParamDefault{no constraint}
  \cgalParamNEnd
  \cgalParamNBegin{point_constrained_direction_map}
    \cgalParamDescription{with `point_is_constrained_map`: the direction of each constrained point (neither zero
                          nor along its normal)}
    \cgalParamType{a model of `ReadablePropertyMap` with the range's value type as key type and `GT::Vector_3` as
                   value type}
    \cgalParamDefault{unused}
  \cgalParamNEnd
  \cgalParamNBegin{alignment_lambda}
    \cgalParamDescription{with a guidance, \f$ \lambda_t \f$, below each component's smallest eigenvalue, as on a mesh}
    \cgalParamDefault{`0`, or just below \f$ \lambda_1 \f$ where \f$ \lambda_1 \f$ is about 0}
  \cgalParamNEnd
  \cgalParamNBegin{alignment_weight}
    \cgalParamDescription{with a guidance, instead of \f$ \lambda_t \f$: the weight \f$ t \in (0, 1) \f$ to
                          reach, as on a mesh}
    \cgalParamDefault{unused}
  \cgalParamNEnd
  \cgalParamNBegin{compute_eigenvalue_bound}
    \cgalParamDescription{whether a guided field also reports \f$ \lambda_1 \f$}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{residual_tolerance}
    \cgalParamDescription{the eigen-solve's relative residual, as on a mesh}
    \cgalParamDefault{`1e-10`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Point_set_direction_field_result`: the normals used, the triangles of the local triangulations and
         the surface triangles, the singular triangles with their indices, and per component what was solved
         (the smallest eigenvalue, the iterations and the residual; with a guidance \f$ \lambda_t \f$ and the
         alignment weight reached)

\throws Invalid_input_error with fewer than 3 points, a coordinate, normal, guidance vector or constrained
        direction that is not finite, a constrained direction that is zero or along its point's normal,
        an option out of range, or no triangle at all (all points on a line, or all at one position)
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
  internal::Point_set_field_request request;
  request.degree = degree;
  request.s = s;
  request.number_of_neighbors = k;
  request.residual_tolerance = choose_parameter(get_parameter(np, internal_np::residual_tolerance), 1e-10);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::point_guidance_map_t>::value)
    request.guidance = internal::point_guidance(points, get_parameter(np, internal_np::point_guidance_map));
  request.curvature = choose_parameter(get_parameter(np, internal_np::principal_curvature_alignment),
                                       Principal_curvature_alignment::NONE);
  if(request.curvature != Principal_curvature_alignment::NONE && degree % 2 != 0)
    throw Invalid_input_error("curvature alignment needs an even degree n (got " + std::to_string(degree) + ")");
  request.alignment = internal::alignment_request(
    np, !request.guidance.empty() || request.curvature != Principal_curvature_alignment::NONE);
  constexpr bool constrained = !parameters::is_default_parameter<NamedParameters, internal_np::point_is_constrained_t>::value;
  static_assert(constrained == !parameters::is_default_parameter<NamedParameters,
                                                                 internal_np::point_constrained_direction_map_t>::value,
                "point_is_constrained_map and point_constrained_direction_map go together");
  if constexpr(constrained)
    internal::point_constraints(points, get_parameter(np, internal_np::point_is_constrained),
                                get_parameter(np, internal_np::point_constrained_direction_map), request);

  internal::Indexed_mesh cloud;
  cloud.points = internal::point_positions(points, NP_helper::get_const_point_map(points, np));
  if(cloud.points.size() < 3)
    throw Invalid_input_error("a point set needs 3 points or more (got " + std::to_string(cloud.points.size()) + ")");
  request.length_scale = internal::normalize_coordinates(cloud);  // the field does not change

  const auto start = std::chrono::steady_clock::now();
  Point_set_direction_field_result result;
  std::vector<internal::Vec3> normals;
  if(internal::names_normals(np)) normals = internal::given_normals(points, NP_helper::get_normal_map(points, np));
  const std::vector<internal::Vec3> directions = internal::Point_set_engine<Default_direction_field_solver>::compute(
    cloud.points, std::move(normals), request, start, result);
  std::size_t i = 0;
  for(const auto& p : points)
  {
    const internal::Vec3& d = directions[i++];
    put(direction_map, p, typename GT::Vector_3(d[0], d[1], d[2]));
  }
  result.timings.total_ms = internal::milliseconds_since(start);
  result.timings.solve_ms = result.timings.total_ms - result.timings.setup_ms - result.timings.factorization_ms;
  return result;
}

#ifndef DOXYGEN_RUNNING
} // inline namespace CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE
#endif

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION
// compiled once, in the library CGAL::Surface_mesh_direction_fields_compiled
extern template struct internal::Point_set_engine<Default_direction_field_solver>;
#endif

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_POINT_SET_DIRECTIONS_H
