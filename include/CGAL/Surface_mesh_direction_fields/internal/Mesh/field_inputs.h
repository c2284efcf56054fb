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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_FIELD_INPUTS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_FIELD_INPUTS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/guidance.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/principal_curvatures.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <array>
#include <vector>

// The inputs of one field computation read from the named parameters: the
// parameters n and s, the guidance field q and the hard constraints; and the
// description of each component.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename GeomTraits>
struct Point_to_array
{
  GeomTraits gt;
  template <typename Point>
  Vec3 operator()(const Point& p) const
  {
    return Vec3{CGAL::to_double(gt.compute_x_3_object()(p)),
                CGAL::to_double(gt.compute_y_3_object()(p)),
                CGAL::to_double(gt.compute_z_3_object()(p))};
  }
};

inline void check_field_parameters(int degree, double s)
{
  if(degree < 1 || degree > maximum_degree)
    throw Invalid_input_error("the degree n must be from 1 to " + std::to_string(maximum_degree) + " (got " +
                              std::to_string(degree) + ")");
  if(!(s >= -1. && s <= 1.))
    throw Invalid_input_error("the smoothness parameter s must lie in [-1, 1] (got " + compact_number(s) + ")");
}

// Euler characteristic of a component: V - E + F with E = (3F + B) / 2, where B
// counts the boundary edges, equal to the number of boundary vertices on a
// manifold mesh (each boundary loop has as many vertices as edges).
inline void describe_component(const Indexed_mesh& m, const Component& comp, Component_report& report)
{
  std::size_t border_vertices = 0;
  for(std::size_t v : comp.vertices)
    border_vertices += m.is_border_vertex[v];
  const long V = static_cast<long>(comp.vertices.size());
  const long F = static_cast<long>(comp.faces.size());
  const long E = (3 * F + static_cast<long>(border_vertices)) / 2;
  report.number_of_vertices = comp.vertices.size();
  report.number_of_faces = comp.faces.size();
  report.euler_characteristic = static_cast<int>(V - E + F);
  report.is_closed = (border_vertices == 0);
}


// A component none of whose faces has an area in the embedding (every one
// below 1e-14 times its longest side squared: all its points on a line, or
// in one point) has no tangent plane anywhere: the mollified lengths would
// give it an intrinsic geometry of needles that says nothing about the
// surface. Only a mesh that needed mollification can have one, so the pass
// runs only then.
inline void check_components_have_area(const Indexed_mesh& m, const Components& comps, double mollification)
{
  if(mollification == 0.) return;
  std::vector<unsigned char> has_area(comps.list.size(), 0);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
  {
    unsigned char& flag = has_area[comps.component_of_face[f]];
    if(flag) continue;
    double area = 0.;
    const Face_geometry g = face_geometry(m, f, 0., &area);
    flag = area > 1e-14 * (std::max)({g.squared_length[0], g.squared_length[1], g.squared_length[2]});
  }
  for(std::size_t c = 0; c < comps.list.size(); ++c)
    if(!has_area[c])
      throw Invalid_input_error("component " + std::to_string(c) + " has no area: every one of its " +
                                std::to_string(comps.list[c].faces.size()) +
                                " faces is degenerate (its points lie on a line)");
}

// Guidance coefficients whose largest length is far from 1 (vectors of length
// 1e200 or 1e-200) are scaled together by a power of two to a largest length
// in [1, 2): the solve and its norms then neither overflow nor underflow. Only
// their ratios matter to the directions.
inline void rescale_extreme_guidance(std::vector<std::complex<double> >& q)
{
  double largest = 0.;
  for(const auto& c : q) largest = (std::max)({largest, std::abs(c.real()), std::abs(c.imag())});
  if(!(largest > 0.) || (largest > 1e-100 && largest < 1e100)) return;
  const int exponent = std::ilogb(largest);
  for(auto& c : q) c = std::complex<double>(std::ldexp(c.real(), -exponent), std::ldexp(c.imag(), -exponent));
}

// The guidance field q (n-th power coefficients per vertex), from the
// principal curvatures and/or a user vector field; empty if there is none.
template <typename VertexDescriptor, typename NamedParameters, typename SparseSolver, typename ToArray>
std::vector<std::complex<double> >
guidance_coefficients(const Indexed_mesh& mesh, const Tangent_spaces& ts, const Components& components,
                      const NamedParameters& np, const std::vector<VertexDescriptor>& vertex_of_index,
                      const std::vector<Vec3>& normals, int degree, SparseSolver& solver, const ToArray& to_array)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  typedef std::complex<double> Complex;
  std::vector<Complex> q;
  const Principal_curvature_alignment curvature =
    choose_parameter(get_parameter(np, internal_np::principal_curvature_alignment), Principal_curvature_alignment::NONE);
  if(curvature != Principal_curvature_alignment::NONE)
  {
    if(degree % 2 != 0)
      throw Invalid_input_error("curvature alignment needs an even degree n (got " + std::to_string(degree) + ")");
    const Principal_curvature_estimate estimate = choose_parameter(
      get_parameter(np, internal_np::principal_curvature_estimate), Principal_curvature_estimate::QUADRIC_FIT);
    const std::vector<Complex> line = estimate == Principal_curvature_estimate::HOPF_DIFFERENTIAL
                                        ? curvature_line_field(mesh, ts, components, solver)
                                        : quadric_fit_line_field(mesh, ts, normals);
    q.assign(mesh.number_of_vertices(), Complex(0., 0.));
    for(const Component& comp : components.list)
      for(std::size_t v : comp.vertices)
      {
        // the minimum-curvature lines are orthogonal to the maximum ones: -w
        const Complex w = curvature == Principal_curvature_alignment::MINIMUM ? -line[v] : line[v];
        q[v] = std::pow(w, degree / 2);
      }
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_guidance_map_t>::value)
  {
    const auto guidance_map = get_parameter(np, internal_np::vertex_guidance_map);
    if(q.empty()) q.assign(mesh.number_of_vertices(), Complex(0., 0.));
    for(std::size_t i = 0; i < vertex_of_index.size(); ++i)
    {
      const Vec3 g = to_array(get(guidance_map, vertex_of_index[i]));
      if(!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(g[2]))
        throw Invalid_input_error("the guidance vector of vertex " + std::to_string(i) + " is not finite");
      // divided by its largest coordinate first, so that no square overflows or underflows
      const double largest = (std::max)({std::abs(g[0]), std::abs(g[1]), std::abs(g[2])});
      if(largest > 0.)
        q[i] += largest * tangent_coefficient(mesh, ts, i, (1. / largest) * g, degree, normals[i]);
    }
  }
  rescale_extreme_guidance(q);
  return q;
}

// Whether the named parameters ask for a guidance field (guidance_coefficients()
// then returns one value per vertex, possibly all zero).
template <typename NamedParameters>
bool requests_guidance(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  return choose_parameter(get_parameter(np, internal_np::principal_curvature_alignment),
                          Principal_curvature_alignment::NONE) != Principal_curvature_alignment::NONE ||
         !is_default_parameter<NamedParameters, internal_np::vertex_guidance_map_t>::value;
}

// How strongly the field follows its guidance: lambda_t, or the alignment
// weight t from which lambda_t is found (user manual, "Aligned and Constrained Fields").
struct Alignment_request
{
  bool lambda_given = false, weight_given = false;
  double lambda = 0., weight = 0.5;
  bool eigenvalue_bound = false;  // lambda_1 asked for, also where the field does not need it
};

template <typename NamedParameters>
Alignment_request alignment_request(const NamedParameters& np, bool has_guidance)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Alignment_request r;
  r.lambda_given = !is_default_parameter<NamedParameters, internal_np::alignment_lambda_t>::value;
  r.weight_given = !is_default_parameter<NamedParameters, internal_np::alignment_weight_t>::value;
  r.lambda = choose_parameter(get_parameter(np, internal_np::alignment_lambda), 0.);
  r.weight = choose_parameter(get_parameter(np, internal_np::alignment_weight), 0.5);
  r.eigenvalue_bound = choose_parameter(get_parameter(np, internal_np::compute_eigenvalue_bound), false);
  if(r.lambda_given && r.weight_given)
    throw Invalid_input_error("give either alignment_lambda or alignment_weight, not both");
  if(r.lambda_given && !std::isfinite(r.lambda))
    throw Invalid_input_error("alignment_lambda must be a finite number");
  if(r.weight_given && !(r.weight > 0. && r.weight < 1.))
    throw Invalid_input_error("alignment_weight must lie in (0, 1) (got " + compact_number(r.weight) + ")");
  if(r.weight_given && !has_guidance)
    throw Invalid_input_error("alignment_weight needs a guidance field (vertex_guidance_map or principal_curvature_alignment)");
  return r;
}

struct Vertex_constraints
{
  std::vector<unsigned char> is_constrained;        // per vertex; empty: no constraint
  std::vector<std::complex<double> > values;        // unit coefficients where constrained
  std::vector<unsigned char> by_user;               // constrained by vertex_is_constrained_map (empty: none)
  // the unit direction the output shows at a constrained vertex (the zero
  // vector: the layout of the coefficient), so that a prescribed direction
  // is met exactly also where the angle rescaling distorts the layout
  std::vector<Vec3> shown;

  void constrain(std::size_t v, std::complex<double> c, const Vec3& direction)
  {
    is_constrained[v] = 1;
    values[v] = c / std::abs(c);
    if(shown.empty()) shown.assign(is_constrained.size(), Vec3{0., 0., 0.});
    shown[v] = direction;
  }
};

// Hard constraints: boundary alignment and/or vertex_is_constrained_map with
// vertex_constrained_direction_map (the latter win where both apply).
template <typename VertexDescriptor, typename NamedParameters, typename ToArray>
Vertex_constraints vertex_constraints(const Indexed_mesh& mesh, const Tangent_spaces& ts, const NamedParameters& np,
                                      const std::vector<VertexDescriptor>& vertex_of_index,
                                      const std::vector<Vec3>& normals, int degree, const ToArray& to_array)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Vertex_constraints vc;
  const Boundary_alignment boundary =
    choose_parameter(get_parameter(np, internal_np::boundary_alignment), Boundary_alignment::NONE);
  constexpr bool has_map = !is_default_parameter<NamedParameters, internal_np::vertex_is_constrained_t>::value;
  if(boundary == Boundary_alignment::NONE && !has_map)
    return vc;
  vc.is_constrained.assign(mesh.number_of_vertices(), 0);
  vc.values.assign(mesh.number_of_vertices(), std::complex<double>(0., 0.));
  if(boundary != Boundary_alignment::NONE)
    for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
      if(mesh.is_border_vertex[v])
      {
        vc.is_constrained[v] = 1;
        vc.values[v] = boundary_coefficient(mesh, ts, v, degree, boundary == Boundary_alignment::NORMAL);
      }
  if constexpr(has_map)
  {
    if constexpr(is_default_parameter<NamedParameters, internal_np::vertex_constrained_direction_map_t>::value)
      throw Invalid_input_error("vertex_is_constrained_map needs vertex_constrained_direction_map");
    else
    {
      const auto is_constrained = get_parameter(np, internal_np::vertex_is_constrained);
      const auto directions = get_parameter(np, internal_np::vertex_constrained_direction_map);
      for(std::size_t i = 0; i < vertex_of_index.size(); ++i)
      {
        const auto v = vertex_of_index[i];
        if(!get(is_constrained, v) || mesh.fan_size(i) == 0) continue;
        Vec3 shown{0., 0., 0.};
        const std::complex<double> c =
          tangent_coefficient(mesh, ts, i, to_array(get(directions, v)), degree, normals[i], &shown);
        if(!(std::abs(c) > 0.) || !std::isfinite(std::abs(c)))
          throw Invalid_input_error("the prescribed direction of constrained vertex " + std::to_string(i) +
                                    " is zero, normal to the surface or not finite");
        vc.constrain(i, c, shown);
        if(vc.by_user.empty()) vc.by_user.assign(mesh.number_of_vertices(), 0);
        vc.by_user[i] = 1;
      }
    }
  }
  return vc;
}

// Hard constraints along sharp features (named parameter
// `edge_is_feature_map`; user manual, section "Aligned and Constrained
// Fields"): at a vertex with exactly two feature edges (inside a feature
// polyline), one of the n directions follows the polyline (the mean of its
// two edge directions); corners (three or more feature edges, or two that
// turn by more than 45 degrees) and the ends of open polylines stay free. Along an edge is a line, not an
// oriented direction, so n must be even. Vertices already constrained by the
// user's map keep their constraint.
template <typename TriangleMesh, typename NamedParameters, typename IndexOfVertex>
void add_feature_constraints(const TriangleMesh& tm, const NamedParameters& np, const IndexOfVertex& index_of,
                             const Indexed_mesh& mesh, const Tangent_spaces& ts, const std::vector<Vec3>& normals,
                             int degree, Vertex_constraints& vc)
{
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_is_feature_t>::value)
  {
    if(degree % 2 != 0)
      throw Invalid_input_error("alignment with sharp features needs an even degree n (got " + std::to_string(degree) +
                                "): along an edge is a line, not an oriented direction");
    const auto is_feature = get_parameter(np, internal_np::edge_is_feature);
    const std::size_t nv = mesh.number_of_vertices();
    std::vector<std::array<std::size_t, 2> > neighbour(nv, {no_index, no_index});
    std::vector<unsigned char> feature_edges(nv, 0);
    auto record = [&](std::size_t v, std::size_t w) {
      if(feature_edges[v] < 2) neighbour[v][feature_edges[v]] = w;
      if(feature_edges[v] < 255) ++feature_edges[v];
    };
    for(auto e : edges(tm))
      if(get(is_feature, e))
      {
        const std::size_t a = index_of(source(halfedge(e, tm), tm)), b = index_of(target(halfedge(e, tm), tm));
        record(a, b);
        record(b, a);
      }
    if(vc.is_constrained.empty())
    {
      vc.is_constrained.assign(nv, 0);
      vc.values.assign(nv, std::complex<double>(0., 0.));
    }
    for(std::size_t v = 0; v < nv; ++v)
    {
      if(feature_edges[v] != 2 || mesh.fan_size(v) == 0 || (!vc.by_user.empty() && vc.by_user[v])) continue;
      const Vec3& p = mesh.points[v];
      const Vec3 in = normalized(p - mesh.points[neighbour[v][0]]), out = normalized(mesh.points[neighbour[v][1]] - p);
      if(!(dot(in, out) >= std::cos(CGAL_PI / 4.))) continue;  // the polyline turns by more than 45 degrees: a corner
      Vec3 shown{0., 0., 0.};
      const std::complex<double> c = tangent_coefficient(mesh, ts, v, in + out, degree, normals[v], &shown);
      if(!(std::abs(c) > 0.) || !std::isfinite(std::abs(c))) continue;  // a feature along the normal: no tangent
      vc.constrain(v, c, shown);
    }
  }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_FIELD_INPUTS_H
