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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FIELD_INPUTS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FIELD_INPUTS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/guidance.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/principal_curvatures.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <array>
#include <vector>

// The inputs of one field computation (Field_request, read from the named
// parameters by named_inputs.h) in the tangent spaces: the guidance field q
// and the hard constraints as coefficients; and the description of each
// component.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

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

// Curvature guidance that a user's vectors join is scaled, per component, to
// an area-weighted root mean square length of 1/10, so that a user vector of
// length 1 weighs ten times the component's typical curvature guidance
// whatever the mesh's size and sampling: strokes are followed at their
// default length (user manual, "Aligned and Constrained Fields"). This scales
// q on the vertices or faces `elements` of one component, `area` the area
// each stands for.
template <typename Index>
void scale_to_tenth_rms(const std::vector<Index>& elements, const std::vector<double>& area,
                        std::vector<std::complex<double> >& q)
{
  double largest = 0.;
  for(std::size_t e : elements) largest = (std::max)(largest, std::abs(q[e]));
  if(!(largest > 0.) || !std::isfinite(largest)) return;
  double weighted = 0., total = 0.;  // of |q / largest|^2: no overflow
  for(std::size_t e : elements)
  {
    weighted += area[e] * std::norm(q[e] / largest);
    total += area[e];
  }
  if(!(weighted > 0.) || !(total > 0.)) return;
  const double rms = largest * std::sqrt(weighted / total);
  for(std::size_t e : elements) q[e] /= 10. * rms;
}

// The same for guidance per vertex (a third of each incident face's area).
inline void scale_to_tenth_rms(const Indexed_mesh& m, const Tangent_spaces& ts, const Components& comps,
                               std::vector<std::complex<double> >& q)
{
  std::vector<double> area(m.number_of_vertices(), 0.);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c) area[m.faces[f][c]] += ts.face_area[f] / 3.;
  for(const Component& comp : comps.list) scale_to_tenth_rms(comp.vertices, area, q);
}

// The guidance field q (n-th power coefficients per vertex), from the
// principal curvatures and/or a user vector field; empty if there is none.
// With both, a vertex's user vector replaces the curvature guidance there,
// in units of a tenth of the component's typical curvature guidance
// (scale_to_tenth_rms()).
template <typename SparseSolver>
std::vector<std::complex<double> >
guidance_coefficients(const Indexed_mesh& mesh, const Tangent_spaces& ts, const Components& components,
                      const Field_request& request, const std::vector<Vec3>& normals, SparseSolver& solver)
{
  typedef std::complex<double> Complex;
  const int degree = request.degree;
  std::vector<Complex> q;
  if(request.curvature != Principal_curvature_alignment::NONE)
  {
    if(degree % 2 != 0)
      throw Invalid_input_error("curvature alignment needs an even degree n (got " + std::to_string(degree) + ")");
    const std::vector<Complex> line = request.curvature_estimate == Principal_curvature_estimate::HOPF_DIFFERENTIAL
                                        ? curvature_line_field(mesh, ts, components, solver)
                                        : quadric_fit_line_field(mesh, ts, normals);
    q.assign(mesh.number_of_vertices(), Complex(0., 0.));
    for(const Component& comp : components.list)
      for(std::size_t v : comp.vertices)
      {
        // the minimum-curvature lines are orthogonal to the maximum ones: -w
        const Complex w = request.curvature == Principal_curvature_alignment::MINIMUM ? -line[v] : line[v];
        q[v] = std::pow(w, degree / 2);
      }
  }
  if(request.has_guidance_map)
  {
    if(q.empty())
      q.assign(mesh.number_of_vertices(), Complex(0., 0.));
    else
      scale_to_tenth_rms(mesh, ts, components, q);
    for(std::size_t i = 0; i < request.guidance.size(); ++i)
    {
      const Vec3& g = request.guidance[i];  // finite (named_inputs.h)
      // divided by its largest coordinate first, so that no square overflows or underflows
      const double largest = (std::max)({std::abs(g[0]), std::abs(g[1]), std::abs(g[2])});
      if(largest > 0.)
        q[i] = largest * tangent_coefficient(mesh, ts, i, (1. / largest) * g, degree, normals[i]);
    }
  }
  rescale_extreme_guidance(q);
  return q;
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
inline Vertex_constraints vertex_constraints(const Indexed_mesh& mesh, const Tangent_spaces& ts,
                                             const Field_request& request, const std::vector<Vec3>& normals)
{
  Vertex_constraints vc;
  if(request.boundary == Boundary_alignment::NONE && !request.has_constraint_map)
    return vc;
  vc.is_constrained.assign(mesh.number_of_vertices(), 0);
  vc.values.assign(mesh.number_of_vertices(), std::complex<double>(0., 0.));
  if(request.boundary != Boundary_alignment::NONE)
    for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
      if(mesh.is_border_vertex[v])
      {
        vc.is_constrained[v] = 1;
        vc.values[v] = boundary_coefficient(mesh, ts, v, request.degree, request.boundary == Boundary_alignment::NORMAL);
      }
  for(std::size_t i = 0; i < request.constrained.size(); ++i)
  {
    if(!request.constrained[i] || mesh.fan_size(i) == 0) continue;
    Vec3 shown{0., 0., 0.};
    const std::complex<double> c =
      tangent_coefficient(mesh, ts, i, request.constrained_direction[i], request.degree, normals[i], &shown);
    if(!(std::abs(c) > 0.) || !std::isfinite(std::abs(c)))
      throw Invalid_input_error("the prescribed direction of constrained vertex " + std::to_string(i) +
                                " is zero, normal to the surface or not finite");
    vc.constrain(i, c, shown);
    if(vc.by_user.empty()) vc.by_user.assign(mesh.number_of_vertices(), 0);
    vc.by_user[i] = 1;
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
inline void add_feature_constraints(const Field_request& request, const Indexed_mesh& mesh, const Tangent_spaces& ts,
                                    const std::vector<Vec3>& normals, Vertex_constraints& vc)
{
  if(!request.has_feature_map) return;
  const int degree = request.degree;
  if(degree % 2 != 0)
    throw Invalid_input_error("alignment with sharp features needs an even degree n (got " + std::to_string(degree) +
                              "): along an edge is a line, not an oriented direction");
  const std::size_t nv = mesh.number_of_vertices();
  std::vector<std::array<std::size_t, 2> > neighbour(nv, {no_index, no_index});
  std::vector<unsigned char> feature_edges(nv, 0);
  auto record = [&](std::size_t v, std::size_t w) {
    if(feature_edges[v] < 2) neighbour[v][feature_edges[v]] = w;
    if(feature_edges[v] < 255) ++feature_edges[v];
  };
  for(const auto& e : request.feature_edges)
  {
    record(e[0], e[1]);
    record(e[1], e[0]);
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

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FIELD_INPUTS_H
