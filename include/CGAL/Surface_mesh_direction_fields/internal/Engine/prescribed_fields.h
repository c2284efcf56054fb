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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_PRESCRIBED_FIELDS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_PRESCRIBED_FIELDS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/component_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/field_targets.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/mesh_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/prescribed_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/singularities.h>

#include <chrono>
#include <complex>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

// Fields with prescribed singularities (user
// manual, "Placing Singularities") and the loop turns every field reports.
// It owns the cycle basis and the factored vertex Laplacian, made once per
// mesh when first needed.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

class Prescribed_fields
{
  typedef std::complex<double> Complex;

public:
  explicit Prescribed_fields(const Mesh_geometry& geometry) : m_geometry(geometry) {}

  // The loops of prescription_loops(), by corner and direction.
  std::vector<Corner_loop> loops()
  {
    const Connection_adjustment& adjustment = prepare();
    std::vector<Corner_loop> loops(adjustment.number_of_loops());
    const Edge_numbering& edges = adjustment.edges();
    for(std::size_t l = 0; l < loops.size(); ++l)
    {
      const Edge_cycle& loop = adjustment.loop(l);
      for(std::size_t i = 0; i < loop.edges.size(); ++i)
        loops[l].emplace_back(edges.corner_of_edge[loop.edges[i]], loop.signs[i] > 0 ? 1 : -1);
    }
    return loops;
  }

  // How the field u turns along the loops of prescription_loops(): what
  // prescribed_loop_turns takes to give its singularities back.
  std::vector<std::pair<std::size_t, int> > loop_turns_of(const std::vector<Complex>& u, const Connection& connection,
                                                          const std::vector<Component_report>& components)
  {
    // loops that can be chosen: 2g through the handles and the boundary loops but one, 1 - chi on a
    // component with boundary, 2 - chi on a closed one; none on spheres and disks (no cycle basis built)
    long loops = 0;
    for(const Component_report& c : components) loops += (c.is_closed ? 2 : 1) - c.euler_characteristic;
    if(loops <= 0) return {};
    prepare();
    return m_adjustment->turns_of_field(m_geometry.mesh, transport_angles(connection), u);
  }

  // The turns of a prescribed field along the loops (the cycle basis exists).
  std::vector<std::pair<std::size_t, int> > turns_of_prescribed(const std::vector<Complex>& u,
                                                                const Connection& connection)
  {
    return m_adjustment->turns_of_field(m_geometry.mesh, transport_angles(connection), u);
  }

  // The parallel field with the prescribed indices k (one per face) and
  // loop turns, before its rotation (rotate()); result.components described.
  std::vector<Complex> field(const Field_request& request, const Connection& connection, Direction_field_result& result)
  {
    prepare();
    if(!m_adjustment->is_factored())  // once per mesh: the factored vertex Laplacian
    {
      const auto factor_start = std::chrono::steady_clock::now();
      m_adjustment->factor(m_geometry.mesh, m_geometry.tangent_spaces);
      result.timings.factorization_ms = milliseconds_since(factor_start);
    }
    const std::vector<int>& k = request.prescribed_index;
    const Loop_turns turns = prescribed_turns(request.loop_turns);
    check_prescription(m_geometry.mesh, m_geometry.components, connection, result.components, k);
    const Eigen::VectorXd& rho = transport_angles(connection);
    const Eigen::VectorXd x = m_adjustment->solve(m_geometry.mesh, connection, rho, k, turns.turns);
    check_free_loops(rho, x, turns);
    result.holonomy_error = m_adjustment->holonomy_error(connection, rho, x, k);
    return parallel_section(m_adjustment->cycle_basis(), m_geometry.mesh.number_of_vertices(), rho, x);
  }

  // The indices of the rotated field, which must be the prescribed ones.
  std::vector<int> checked_indices(const Field_request& request, const Connection& connection,
                                   const std::vector<Complex>& u)
  {
    const std::vector<int> index =
      face_indices_with_edge_angles(m_geometry.mesh, connection, m_adjustment->edges(), transport_angles(connection), u);
    check_prescribed_indices(index, request.prescribed_index, request.loop_turns.empty());
    return index;
  }

  // The rotation of component c's parallel field: by its first constrained
  // vertex (the others must agree), or the one that best follows the
  // guidance (the angle of sum_v area_v q_v conj(u_v)).
  void rotate(std::size_t c, const Field_targets& targets, std::vector<Complex>& u) const
  {
    const Component& comp = m_geometry.components.list[c];
    const Vertex_constraints& constraints = targets.constraints;
    Complex rotation(0., 0.);
    for(std::size_t v : comp.vertices)
      if(!constraints.is_constrained.empty() && constraints.is_constrained[v])
      {
        if(rotation == Complex(0., 0.))
          rotation = constraints.values[v] / u[v];
        else
          check_constraint_agrees(v, constraints.values[v], rotation * u[v]);
      }
    if(rotation == Complex(0., 0.) && !targets.guidance.empty())
      for(std::size_t v : comp.vertices)
      {
        double area = 0.;
        for(std::size_t corner : m_geometry.mesh.fan(v)) area += m_geometry.tangent_spaces.face_area[corner / 3];
        rotation += area * targets.guidance[v] * std::conj(u[v]);
      }
    if(!(std::abs(rotation) > 0.) || !std::isfinite(std::abs(rotation))) return;
    rotation /= std::abs(rotation);
    for(std::size_t v : comp.vertices) u[v] *= rotation;
  }

  // The requests that have no meaning for a prescribed field (it solves no
  // eigenproblem and no aligned system).
  static void refuse_other_requests(const Field_request& request)
  {
    if(request.alignment.lambda_given || request.alignment.weight_given)
      throw Invalid_input_error("alignment_lambda and alignment_weight do not apply to prescribed singularities "
                                "(the guidance only chooses the field's rotation)");
    if(request.alignment.eigenvalue_bound)
      throw Invalid_input_error("compute_eigenvalue_bound does not apply to prescribed singularities");
    if(request.distributed != nullptr)
      throw Invalid_input_error("prescribed singularities are computed by one process: no distributed_solver");
  }

private:
  // The turns asked of the loops of prescription_loops() (0 where not asked).
  struct Loop_turns
  {
    std::vector<int> turns;
    std::vector<unsigned char> asked;
  };

  Connection_adjustment& prepare()
  {
    if(!m_adjustment) m_adjustment = std::make_unique<Connection_adjustment>(m_geometry.mesh, m_geometry.components);
    return *m_adjustment;
  }

  // rho_e of the connection (of its degree), per edge
  const Eigen::VectorXd& transport_angles(const Connection& connection)
  {
    if(m_transport_angles_degree != connection.degree)
    {
      m_transport_angles = m_adjustment->transport_angles(connection);
      m_transport_angles_degree = connection.degree;
    }
    return m_transport_angles;
  }

  template <typename Range>
  Loop_turns prescribed_turns(const Range& given) const
  {
    Loop_turns t;
    t.turns.assign(m_adjustment->number_of_loops(), 0);
    t.asked.assign(t.turns.size(), 0);
    for(const auto& entry : given)
    {
      const std::size_t l = static_cast<std::size_t>(entry.first);
      if(l >= t.turns.size())
        throw Invalid_input_error("prescribed_loop_turns names loop " + std::to_string(l) + ", but the mesh has " +
                                  std::to_string(t.turns.size()) + " (see prescription_loops())");
      if(t.asked[l]++) throw Invalid_input_error("prescribed_loop_turns lists loop " + std::to_string(l) + " twice");
      if(entry.second < -maximum_degree || entry.second > maximum_degree)
        throw Invalid_input_error("prescribed_loop_turns asks " + std::to_string(entry.second) + " turns of loop " +
                                  std::to_string(l) + " (at most " + std::to_string(maximum_degree) + " either way)");
      t.turns[l] = static_cast<int>(entry.second);
    }
    return t;
  }

  // A free boundary loop (the longest of its component) turns as the other
  // loops and the indices imply; turns asked of it must be those.
  void check_free_loops(const Eigen::VectorXd& rho, const Eigen::VectorXd& x, const Loop_turns& asked) const
  {
    for(std::size_t l = 0; l < asked.turns.size(); ++l)
    {
      if(!asked.asked[l] || !m_adjustment->is_free_loop(l)) continue;
      const int found = m_adjustment->turns_of(l, rho, x);
      if(found != asked.turns[l])
        throw Invalid_input_error("loop " + std::to_string(l) + " (the longest boundary loop of component " +
                                  std::to_string(m_adjustment->loop(l).component) + ") turns " +
                                  std::to_string(found) + " times with these indices and the other loops' turns, not " +
                                  std::to_string(asked.turns[l]) + " (the indices of a component and the turns of its "
                                  "boundary loops add up to a fixed sum)");
    }
  }

  static void check_constraint_agrees(std::size_t v, Complex wanted, Complex found)
  {
    const double degrees = std::abs(std::arg(wanted / found)) * 180. / CGAL_PI;
    if(degrees > 1e-6)
      throw Invalid_input_error("constrained vertex " + std::to_string(v) + " differs from the prescribed field by " +
                                compact_number(degrees) +
                                " degrees (in the n-th power): with prescribed singularities only one constrained "
                                "vertex per component fixes the rotation, the others must agree with it");
  }

  // The indices of the parallel field are the prescribed ones unless some
  // |x_e| reached pi, which the last stage of Connection_adjustment::solve()
  // avoids wherever it can: then the prescription asks more of an edge than
  // the field can turn along it (singularities in neighbouring faces, or a
  // vertex whose angle defect times n is a full turn or more, as at the
  // corners of a cube, made singularity-free). A surface with handles or
  // several boundary loops may need the turns along its loops as well: the
  // least change with 0 turns can pass pi along an edge where the field's own
  // turns would not.
  void check_prescribed_indices(const std::vector<int>& index, const std::vector<int>& k, bool no_turns_given) const
  {
    for(std::size_t f = 0; f < k.size(); ++f)
      if(index[f] != k[f])
        throw Invalid_input_error(
          "the field with these singularities would turn by more than pi along an edge of face " + std::to_string(f) +
          " (index " + std::to_string(index[f]) + " instead of " + std::to_string(k[f]) + "): " +
          (no_turns_given && m_adjustment->number_of_loops() > 0
             ? "give the turns along the surface's loops as well (a field's own are in its result's loop_turns), or "
             : "") +
          "spread singularities that are close together, or refine the mesh where curvature is concentrated" +
            face_field_can_show(),
          f);
  }

  const Mesh_geometry& m_geometry;
  std::unique_ptr<Connection_adjustment> m_adjustment;  // made when first needed
  Eigen::VectorXd m_transport_angles;                   // rho_e per edge, of the degree below
  int m_transport_angles_degree = 0;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_PRESCRIBED_FIELDS_H
