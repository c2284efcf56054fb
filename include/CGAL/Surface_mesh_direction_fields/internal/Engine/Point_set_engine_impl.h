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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_POINT_SET_ENGINE_IMPL_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_POINT_SET_ENGINE_IMPL_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Point_set_engine.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/point_set_field.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/progress_report.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/local_triangulations.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/point_set_connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/point_set_fits.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstddef>
#include <tuple>
#include <vector>

// The definition of Point_set_engine (Point_set_engine.h): the normals
// estimated where not given, the local triangulations, the eigen-solve per
// component and what the result reports (user manual, section "Point Sets").

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Unit normals fitted over k neighbours (point_set_fitted_normals()),
// oriented by CGAL's minimum spanning tree; a normal that the tree leaves
// unoriented is kept as fitted.
inline std::vector<Vec3> estimated_normals(const std::vector<Vec3>& positions, const Neighbour_search& search,
                                           unsigned int k)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
  typedef std::tuple<Kernel::Point_3, Kernel::Vector_3, std::size_t> Sample;
  const std::vector<Vec3> fitted = point_set_fitted_normals(positions, search, k);
  std::vector<Sample> samples;
  for(std::size_t i = 0; i < positions.size(); ++i)
    samples.emplace_back(Kernel::Point_3(positions[i][0], positions[i][1], positions[i][2]),
                         Kernel::Vector_3(fitted[i][0], fitted[i][1], fitted[i][2]), i);
  const auto np = CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Sample>())
                    .normal_map(CGAL::Nth_of_tuple_property_map<1, Sample>());
  CGAL::mst_orient_normals(samples, k, np);
  std::vector<Vec3> normals(positions.size());
  for(const Sample& s : samples)
  {
    const Kernel::Vector_3& v = std::get<1>(s);
    normals[std::get<2>(s)] = normalized(Vec3{v.x(), v.y(), v.z()});
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

// `length_scale`: of normalize_coordinates() (eigenvalues scale like the inverse of an area).
inline void report_point_set(const Point_set_domain& d, const Point_set_solution& solution, double length_scale,
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
    static_cast<Component_solve_report&>(report) = c.report;
    report.number_of_vertices = c.points.size();
    report.number_of_faces = c.faces.size();
    if(report.eigenvalue) *report.eigenvalue *= length_scale * length_scale;
    report.lambda *= length_scale * length_scale;
    result.components.push_back(report);
    covered += c.points.size();
  }
  result.number_of_points_without_triangles = m.number_of_vertices() - covered;
  std::tie(result.surface_euler_characteristic, result.surface_is_closed) = surface_characteristic(d, sides, result.on_surface);
}

template <typename SparseSolver>
std::vector<Vec3> Point_set_engine<SparseSolver>::compute(const std::vector<Vec3>& positions, std::vector<Vec3> normals,
                                                          const Point_set_field_request& request,
                                                          std::chrono::steady_clock::time_point start,
                                                          Point_set_direction_field_result& result)
{
  const Neighbour_search search(positions);
  if(normals.empty())
  {
    normals = estimated_normals(positions, search, request.number_of_neighbors);
    result.normals_estimated = true;
    result.normals_ms = milliseconds_since(start);
  }
  const Local_triangles local = local_triangulations(positions, normals, search, request.number_of_neighbors);
  const Point_set_domain domain = make_point_set_domain(positions, normals, local, request.degree);
  if(domain.triangles.number_of_faces() == 0)
    throw Invalid_input_error("the points span no triangle (all on a line or at one position)");
  std::vector<Vec3> curvature;  // fitted to twice the neighbours of a triangulation: a two-ring's worth
  if(request.curvature != Principal_curvature_alignment::NONE)
    curvature = point_set_curvature_vectors(positions, normals, search, 2 * std::size_t(request.number_of_neighbors));

  Eigen_solve_options options;
  options.residual_tolerance = request.residual_tolerance;
  const double before_solve = milliseconds_since(start);
  const Point_set_solution solution = solve_point_set_field<SparseSolver>(domain, request, curvature, options);
  report_point_set(domain, solution, request.length_scale, result);
  result.timings.factorization_ms = solution.timings.factorization_ms;
  result.timings.setup_ms = before_solve + solution.timings.setup_ms;
  result.normals = normals;
  result.magnitudes = relative_magnitudes(solution);

  std::vector<Vec3> directions(positions.size(), Vec3{0., 0., 0.});
  for(std::size_t i = 0; i < positions.size(); ++i)
  {
    const std::complex<double> u = solution.coefficients[i];
    if(std::abs(u) > 0.) directions[i] = point_direction(domain, i, std::arg(u) / request.degree);
  }
  return directions;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_POINT_SET_ENGINE_IMPL_H
