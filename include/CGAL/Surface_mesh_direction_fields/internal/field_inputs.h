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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_INPUTS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_INPUTS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/internal/aligned_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/guidance.h>
#include <CGAL/Surface_mesh_direction_fields/internal/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tangent_spaces.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <complex>
#include <string>
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
  if(degree < 1)
    throw Invalid_input_error("the degree n must be at least 1 (got " + std::to_string(degree) + ")");
  if(!(s >= -1. && s <= 1.))
    throw Invalid_input_error("the smoothness parameter s must lie in [-1, 1] (got " + std::to_string(s) + ")");
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
    // The Hopf differential is a line field (n = 2): its coefficients solve
    // M_2 q = q~ with the mass matrix of the degree-2 connection.
    const std::vector<Complex> pairing = hopf_differential_pairing(mesh, ts);
    const Connection line_connection = compute_connection(mesh, ts, 2);
    q.assign(mesh.number_of_vertices(), Complex(0., 0.));
    const std::vector<Energy_and_mass> line_matrices = assemble_energy_and_mass(mesh, ts, line_connection, components, 0.);
    for(std::size_t c = 0; c < components.list.size(); ++c)
    {
      const Component& comp = components.list[c];
      const Energy_and_mass& em = line_matrices[c];
      Complex_vector rhs(static_cast<Eigen::Index>(comp.vertices.size()));
      for(std::size_t i = 0; i < comp.vertices.size(); ++i) rhs[static_cast<Eigen::Index>(i)] = pairing[comp.vertices[i]];
      Factored_matrix<SparseSolver> factored(solver);
      const Complex_vector line = solve_aligned_system(em.mass, em.mass, 0., rhs, Constraints(), factored);
      for(std::size_t i = 0; i < comp.vertices.size(); ++i)
      {
        Complex w = line[static_cast<Eigen::Index>(i)];
        if(curvature == Principal_curvature_alignment::MINIMUM) w = -w;  // the orthogonal line field
        q[comp.vertices[i]] = std::pow(w, degree / 2);
      }
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
      q[i] += tangent_coefficient(mesh, ts, i, g, degree, normals[i]);
    }
  }
  return q;
}

struct Vertex_constraints
{
  std::vector<unsigned char> is_constrained;        // per vertex; empty: no constraint
  std::vector<std::complex<double> > values;        // unit coefficients where constrained
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
        const std::complex<double> c = tangent_coefficient(mesh, ts, i, to_array(get(directions, v)), degree, normals[i]);
        if(!(std::abs(c) > 0.) || !std::isfinite(std::abs(c)))
          throw Invalid_input_error("the prescribed direction of constrained vertex " + std::to_string(i) +
                                    " is zero, normal to the surface or not finite");
        vc.is_constrained[i] = 1;
        vc.values[i] = c / std::abs(c);
      }
    }
  }
  return vc;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_INPUTS_H
