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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_POINT_SET_FIELD_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_POINT_SET_FIELD_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Point_set_engine.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/component_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/progress_report.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/sequential_component_systems.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_inputs.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/point_set_connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/singularities.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

// The field of a point set (user manual, "Point Sets"): the triangles of the
// local triangulations split the points into components (points joined by a
// triangle), and each component's field is solved as on a mesh.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Point_set_component
{
  std::vector<std::size_t> points, faces;
  Component_solve_report report;  // eigenvalue and lambda_t in the normalized coordinates' units
};

struct Point_set_solution
{
  std::vector<Complex> coefficients;  // per point; 0 for a point of no triangle
  std::vector<Point_set_component> components;
  std::vector<int> face_index;        // per triangle of the domain
  Direction_field_timings timings;    // the assembly (setup_ms) and the factorizations
};

inline std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i)
{
  while(parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The components of the points that belong to a triangle, each with its
// triangles, in the order of their smallest point.
inline std::vector<Point_set_component> point_set_components(const Indexed_mesh& m)
{
  const std::size_t np = m.number_of_vertices();
  std::vector<std::size_t> parent(np);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  std::vector<unsigned char> covered(np, 0);
  for(const auto& t : m.faces)
    for(int c = 0; c < 3; ++c)
    {
      covered[t[c]] = 1;
      const std::size_t a = find_root(parent, t[c]), b = find_root(parent, t[(c + 1) % 3]);
      if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b);
    }
  std::vector<Point_set_component> components;
  std::vector<std::size_t> component_of_root(np, no_point);
  for(std::size_t p = 0; p < np; ++p)
  {
    if(!covered[p]) continue;
    std::size_t& c = component_of_root[find_root(parent, p)];
    if(c == no_point)
    {
      c = components.size();
      components.emplace_back();
    }
    components[c].points.push_back(p);
  }
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    components[component_of_root[find_root(parent, m.faces[f][0])]].faces.push_back(f);
  return components;
}

// The coefficient |w| exp(i n theta) of a vector w at point i, theta its
// angle in the tangent plane from the reference direction X_i (the
// direction of angle theta is point i's output for that coefficient).
inline Complex point_coefficient(const Point_set_domain& d, std::size_t i, const Vec3& w, int degree)
{
  const Vec3& n = d.normals[i];
  const Vec3 tangent = w - dot(w, n) * n;
  const double length = norm(tangent);
  if(!(length > 0.)) return Complex(0., 0.);
  const double theta = std::atan2(dot(tangent, cross(n, d.reference[i])), dot(tangent, d.reference[i]));
  return std::polar(length, degree * theta);
}

// The area each point stands for: a third of each of its triangles' areas,
// a triangle weighing (holders / 3) as in the matrices.
inline std::vector<double> point_areas(const Point_set_domain& d)
{
  std::vector<double> area(d.triangles.number_of_vertices(), 0.);
  for(std::size_t f = 0; f < d.triangles.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c) area[d.triangles.faces[f][c]] += d.tangent.face_area[f] * d.holders[f] / 9.;
  return area;
}

// The guidance coefficients q per point (empty: none), as on a mesh (user
// manual, "Aligned and Constrained Fields"): the (n/2)-th power of the
// principal-curvature line field (k_max - k_min) exp(2 i theta), turned by a
// right angle for the minimum curvature; where the user gives a nonzero
// vector, its coefficient instead, the curvature guidance then scaled per
// component to a root mean square of 1/10.
inline std::vector<Complex> point_set_guidance(const Point_set_domain& d,
                                               const std::vector<Point_set_component>& components,
                                               const Point_set_field_request& request,
                                               const std::vector<Vec3>& curvature)
{
  const std::size_t np = d.triangles.number_of_vertices();
  std::vector<Complex> q;
  if(!curvature.empty())
  {
    q.assign(np, Complex(0., 0.));
    const bool minimum = request.curvature == Principal_curvature_alignment::MINIMUM;
    for(std::size_t i = 0; i < np; ++i)
    {
      const Complex line = point_coefficient(d, i, curvature[i], 2);
      q[i] = std::pow(minimum ? -line : line, request.degree / 2);
    }
  }
  if(request.guidance.empty()) return q;
  if(q.empty())
    q.assign(np, Complex(0., 0.));
  else
  {
    const std::vector<double> area = point_areas(d);
    for(const Point_set_component& comp : components) scale_to_tenth_rms(comp.points, area, q);
  }
  for(std::size_t i = 0; i < np; ++i)
  {
    const Vec3& g = request.guidance[i];  // finite; divided by its largest coordinate, so that no square overflows
    const double largest = (std::max)({std::abs(g[0]), std::abs(g[1]), std::abs(g[2])});
    if(largest > 0.) q[i] = largest * point_coefficient(d, i, (1. / largest) * g, request.degree);
  }
  return q;
}

// Component `comp`'s hard constraints: the unit coefficient of each
// constrained point's direction (none if the request has none).
inline Constraints point_set_constraints(const Point_set_domain& d, const Point_set_component& comp,
                                         const Point_set_field_request& request)
{
  Constraints local;
  if(request.is_constrained.empty()) return local;
  local.is_constrained.assign(comp.points.size(), 0);
  local.values = Complex_vector::Zero(static_cast<Eigen::Index>(comp.points.size()));
  for(std::size_t a = 0; a < comp.points.size(); ++a)
  {
    const std::size_t p = comp.points[a];
    if(!request.is_constrained[p]) continue;
    const Vec3& w = request.constrained_directions[p];  // finite; its length does not matter
    const double largest = (std::max)({std::abs(w[0]), std::abs(w[1]), std::abs(w[2])});
    const Complex c = largest > 0. ? point_coefficient(d, p, (1. / largest) * w, request.degree) : Complex(0., 0.);
    if(!(std::abs(c) > 0.))
      throw Invalid_input_error("the constrained direction of point " + std::to_string(p) +
                                " is zero or along its normal");
    local.is_constrained[a] = 1;
    local.values[static_cast<Eigen::Index>(a)] = c / std::abs(c);
  }
  return local;
}

// The field of each component (user manual, "Point Sets"): the smallest
// eigenvector of its pencil, or with guidance coefficients `q` (per point,
// or none) and hard constraints the aligned solve, as on a mesh
// (Component_fields). The matrices are freed on return.
template <typename SparseSolver>
void solve_point_set_components(const Point_set_domain& d, const Point_set_field_request& request,
                                const std::vector<Complex>& q, const Eigen_solve_options& options,
                                Point_set_solution& solution)
{
  std::vector<std::size_t> unknowns;
  for(const Point_set_component& comp : solution.components) unknowns.push_back(comp.points.size());
  Sequential_component_systems<SparseSolver> systems(std::move(unknowns), request.length_scale, nullptr);
  Alignment_request alignment = request.alignment;
  alignment.lambda = systems.eigenvalue_from_user(alignment.lambda);
  SparseSolver linear_solver;
  Component_fields<Sequential_component_systems<SparseSolver> > fields(systems, options, linear_solver,
                                                                      solution.timings);
  std::vector<std::size_t> local_index(d.triangles.number_of_vertices(), no_point);
  for(std::size_t c = 0; c < solution.components.size(); ++c)
  {
    Point_set_component& comp = solution.components[c];
    const auto start = std::chrono::steady_clock::now();
    const auto size = static_cast<Eigen::Index>(comp.points.size());
    for(std::size_t a = 0; a < comp.points.size(); ++a) local_index[comp.points[a]] = a;
    Energy_and_mass em;
    assemble_point_set(d, comp.faces, local_index, size, request.s, em.energy, em.mass);
    systems.set_matrices(c, std::move(em));
    solution.timings.setup_ms += milliseconds_since(start);
    Complex_vector component_q;
    if(!q.empty()) component_q.resize(size);
    for(std::size_t a = 0; a < comp.points.size() && !q.empty(); ++a)
      component_q[static_cast<Eigen::Index>(a)] = q[comp.points[a]];
    const Complex_vector u = fields.field_of(c, component_q, point_set_constraints(d, comp, request), alignment,
                                             comp.report);
    if(u.size() != size) throw Solver_failure_error("the solve of a point set's component failed");
    for(std::size_t a = 0; a < comp.points.size(); ++a)
      solution.coefficients[comp.points[a]] = u[static_cast<Eigen::Index>(a)];
  }
}

// `curvature`: the maximum-curvature vector per point where the request asks
// for curvature alignment (point_set_fits.h), else empty.
template <typename SparseSolver>
Point_set_solution solve_point_set_field(const Point_set_domain& d, const Point_set_field_request& request,
                                         const std::vector<Vec3>& curvature, const Eigen_solve_options& options)
{
  Point_set_solution solution;
  solution.coefficients.assign(d.triangles.number_of_vertices(), Complex(0., 0.));
  solution.components = point_set_components(d.triangles);
  std::vector<Complex> q = point_set_guidance(d, solution.components, request, curvature);
  rescale_extreme_guidance(q);
  solve_point_set_components<SparseSolver>(d, request, q, options, solution);
  solution.face_index = face_indices(d.triangles, d.connection, solution.coefficients);
  return solution;
}

// The directed sides of the triangles, numbered: side_of[3f+c] is the number
// of the side faces[f][c] -> faces[f][c+1], the same for every triangle that
// has it; twin[s] is the number of the reverse side, or no_point.
struct Directed_sides
{
  std::vector<std::size_t> side_of, twin;
};

inline Directed_sides directed_sides(const Indexed_mesh& m)
{
  const std::size_t nc = 3 * m.number_of_faces();
  std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::size_t> > keyed(nc);
  for(std::size_t ci = 0; ci < nc; ++ci)
    keyed[ci] = {{m.vertex_of_corner(ci), m.vertex_of_corner(Indexed_mesh::next_corner(ci))}, ci};
  std::sort(keyed.begin(), keyed.end());
  Directed_sides sides;
  sides.side_of.resize(nc);
  std::vector<std::pair<std::size_t, std::size_t> > keys;
  for(const auto& k : keyed)
  {
    if(keys.empty() || keys.back() != k.first) keys.push_back(k.first);
    sides.side_of[k.second] = keys.size() - 1;
  }
  sides.twin.resize(keys.size());
  for(std::size_t s = 0; s < keys.size(); ++s)
  {
    const auto reverse = std::make_pair(keys[s].second, keys[s].first);
    const auto it = std::lower_bound(keys.begin(), keys.end(), reverse);
    sides.twin[s] = (it != keys.end() && *it == reverse) ? std::size_t(it - keys.begin()) : no_point;
  }
  return sides;
}

// The triangles that make the point set's surface, where its singularities
// are read: taken in the order of their holders (3, 2, then 1) and then of
// their number, a triangle joins unless one of its sides, in its direction,
// is a side of a triangle that joined before. Every side then lies in at most
// two of them, turned opposite ways: where two local triangulations cut a
// quadrilateral along different diagonals, only one cut is kept.
inline std::vector<unsigned char> surface_triangles(const Point_set_domain& d, const Directed_sides& sides)
{
  const Indexed_mesh& m = d.triangles;
  std::vector<std::size_t> order(m.number_of_faces());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&d](std::size_t a, std::size_t b) { return d.holders[a] > d.holders[b]; });
  std::vector<unsigned char> used(sides.twin.size(), 0), on_surface(m.number_of_faces(), 0);
  for(std::size_t f : order)
  {
    const std::size_t* s = sides.side_of.data() + 3 * f;
    if(used[s[0]] || used[s[1]] || used[s[2]]) continue;
    used[s[0]] = used[s[1]] = used[s[2]] = 1;
    on_surface[f] = 1;
  }
  return on_surface;
}

// The Euler characteristic V - E + F of the surface triangles, and whether
// they close up (every side in two of them).
inline std::pair<int, bool> surface_characteristic(const Point_set_domain& d, const Directed_sides& sides,
                                                   const std::vector<unsigned char>& on_surface)
{
  const Indexed_mesh& m = d.triangles;
  std::vector<unsigned char> used_point(m.number_of_vertices(), 0), used_side(sides.twin.size(), 0);
  long faces = 0;
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
  {
    if(!on_surface[f]) continue;
    ++faces;
    for(int c = 0; c < 3; ++c)
    {
      used_point[m.faces[f][c]] = 1;
      used_side[sides.side_of[3 * f + c]] = 1;
    }
  }
  long directed = 0, unpaired = 0;
  for(std::size_t s = 0; s < used_side.size(); ++s)
  {
    if(!used_side[s]) continue;
    ++directed;
    if(sides.twin[s] == no_point || !used_side[sides.twin[s]]) ++unpaired;
  }
  const long edges = (directed + unpaired) / 2;
  const long vertices = std::count(used_point.begin(), used_point.end(), 1);
  return {static_cast<int>(vertices - edges + faces), faces > 0 && unpaired == 0};
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_POINT_SET_FIELD_H
