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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FACE_FIELD_ENGINE_IMPL_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FACE_FIELD_ENGINE_IMPL_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Face_field_engine.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/component_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/progress_report.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/sequential_component_systems.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/face_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/face_prescription.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/prescribed_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/singularity_cancellation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_inputs.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

// The definitions of the engine of fields on faces (Face_field_engine.h):
// the mesh's intrinsic geometry and dual connection once, then per component
// the smallest eigenvector of the pencil on faces or the aligned /
// constrained solve (or the prescribed singularities' parallel field), and
// at the end the indices at the vertices and the matching (user manual,
// section "Fields on Faces").

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The hard constraints on faces: per face, 0 or the n-th power of the
// direction it must have (a unit complex number), from the feature edges,
// the boundary and the user's constrained faces (which win).
inline std::vector<Complex> face_constraints(const Indexed_mesh& m, const Tangent_spaces& ts,
                                             const Dual_connection& dc, const Face_field_request& request)
{
  const int n = request.degree;
  std::vector<Complex> sum(m.number_of_faces(), Complex(0., 0.)), first(m.number_of_faces(), Complex(0., 0.));
  auto add = [&](std::size_t f, double angle) {
    const Complex value = std::polar(1., static_cast<double>(n) * angle);
    if(first[f] == Complex(0., 0.)) first[f] = value;
    sum[f] += value;
  };
  std::unordered_set<unsigned long long> features;
  const unsigned long long nv = m.number_of_vertices();
  for(const auto& e : request.feature_edges)
    features.insert((std::min)(e[0], e[1]) * nv + (std::max)(e[0], e[1]));
  const double boundary_turn = request.boundary == Boundary_alignment::NORMAL ? 0.5 * CGAL_PI : 0.;
  for(std::size_t corner = 0; corner < 3 * m.number_of_faces(); ++corner)
  {
    const std::size_t f = corner / 3, a = m.vertex_of_corner(corner);
    const std::size_t b = m.vertex_of_corner(Indexed_mesh::next_corner(corner));
    const double angle = side_angle(ts, f, static_cast<int>(corner % 3));
    if(m.twin_corner[corner] == no_index && !dc.is_glued[corner] && request.boundary != Boundary_alignment::NONE)
      add(f, angle + boundary_turn);
    else if(!features.empty() && features.count((std::min)(a, b) * nv + (std::max)(a, b)))
      add(f, angle);
  }
  std::vector<Complex> c(m.number_of_faces(), Complex(0., 0.));
  for(std::size_t f = 0; f < c.size(); ++f)
  {
    if(!request.constrained.empty() && request.constrained[f])
    {
      c[f] = std::polar(1., static_cast<double>(n) * angle_in_face(m, f, request.constrained_direction[f]));
      continue;
    }
    // two sides that disagree (n times their angle) leave the first one's direction
    c[f] = std::abs(sum[f]) > 1e-6 ? sum[f] / std::abs(sum[f]) : first[f];
  }
  return c;
}

// The guidance on faces: the curvature line field raised to n / 2 (keeping
// its magnitude, the difference of the principal curvatures), and the
// user's vectors (projected, their length their weight), which replace the
// curvature guidance where they are given, a length of 1 ten times its
// typical length.
inline std::vector<Complex> face_guidance(const Indexed_mesh& m, const Tangent_spaces& ts, const Components& comps,
                                          const Face_field_request& request)
{
  const int n = request.degree;
  std::vector<Complex> q(m.number_of_faces(), Complex(0., 0.));
  if(request.curvature != Principal_curvature_alignment::NONE)
  {
    const std::vector<Complex> line = face_curvature_line_field(m, ts);
    const double turn = request.curvature == Principal_curvature_alignment::MINIMUM ? CGAL_PI : 0.;
    for(std::size_t f = 0; f < q.size(); ++f)
      q[f] = std::polar(std::abs(line[f]), 0.5 * static_cast<double>(n) * (std::arg(line[f]) + turn));
  }
  if(request.guidance.empty()) return q;
  if(request.curvature != Principal_curvature_alignment::NONE)  // per component, as on vertices
    for(const Component& comp : comps.list) scale_to_tenth_rms(comp.faces, ts.face_area, q);
  for(std::size_t f = 0; f < q.size(); ++f)
  {
    const Vec3 normal = face_frame(m, f)[1];
    const Vec3& w = request.guidance[f];
    const double length = norm(w - dot(w, normal) * normal);
    if(length > 0.) q[f] = std::polar(length, static_cast<double>(n) * angle_in_face(m, f, w));
  }
  return q;
}

template <typename SparseSolver>
class Face_field_engine<SparseSolver>::Impl
{
  typedef std::chrono::steady_clock Clock;

public:
  Impl(Indexed_mesh mesh, double mollification, const std::vector<std::size_t>& point_of_vertex)
    : m_mesh(std::move(mesh))
  {
    m_length_scale = normalize_coordinates(m_mesh);
    m_components = split_into_components(m_mesh);
    m_spaces = compute_tangent_spaces(m_mesh, mollification);
    check_components_have_area(m_mesh, m_components, m_spaces.mollification);
    m_dual = dual_connection(m_mesh, m_spaces, point_of_vertex);
    std::vector<std::pair<std::size_t, std::size_t> > coupled;
    for(const Dual_connection::Glued_pair& glued : m_dual.glued)
      coupled.emplace_back(glued.corner / 3, glued.other / 3);
    join_components(m_components, coupled);
  }

  Face_direction_field_result compute(const Face_field_request& request, const SparseSolver* user_solver,
                                      Face_field_answer& answer) const
  {
    if(!m_dual.glued.empty() && (request.prescribed || request.cancellation_radius > 0.))
      throw Invalid_input_error(
        std::string(request.prescribed ? "prescribed_singularities" : "singularity_cancellation_radius") +
        " is not available where non-manifold edges are glued (vertex_point_index_map)");
    if(request.prescribed) return compute_prescribed(request, answer);
    const Face_direction_field_result optimal = compute_optimal(request, user_solver, answer);
    if(request.cancellation_radius == 0.) return optimal;
    if(follows_constraints(request)) return with_pairs_turned_away(request, optimal, answer);
    return with_cancelled_pairs(request, optimal, answer);
  }

  const Indexed_mesh& mesh() const { return m_mesh; }

private:
  // The smoothest (or aligned) field's singular pairs of opposite indices
  // within the request's radius cancelled (user manual, section "Fields on
  // Faces"): the parallel field with the singularities that remain, its
  // timings the sum of both computations. Where that field turns by pi/n or
  // more across an edge, or so nearly that (readers that recompute the
  // matching would see other singularities), the cancelled pair nearest that
  // edge is given back, and the field computed again (a sweep and two solves
  // on the kept factor).
  Face_direction_field_result with_cancelled_pairs(const Face_field_request& request,
                                                   const Face_direction_field_result& optimal,
                                                   Face_field_answer& answer) const
  {
    const Face_field_answer optimal_answer = answer;
    const std::vector<int>& own = optimal_answer.vertex_index;
    Face_field_request parallel = request;
    parallel.prescribed_index = own;
    std::vector<std::pair<std::size_t, std::size_t> > pairs = cancel_singularity_pairs(
      m_mesh, request.cancellation_radius * bounding_box_diagonal(m_mesh), parallel.prescribed_index);
    if(pairs.empty()) return optimal;
    parallel.prescribed = true;
    std::vector<unsigned char> doubtful;
    Face_direction_field_result result = compute_prescribed(parallel, answer, &doubtful);
    const auto any_doubtful = [&] { return std::find(doubtful.begin(), doubtful.end(), 1) != doubtful.end(); };
    while(any_doubtful() && !pairs.empty())
    {
      std::vector<unsigned char> given_back(pairs.size(), 0);
      for(std::size_t side = 0; side < doubtful.size(); ++side)
        if(doubtful[side]) given_back[closest_pair(m_mesh, pairs, m_mesh.vertex_of_corner(side))] = 1;
      std::vector<std::pair<std::size_t, std::size_t> > still;
      for(std::size_t i = 0; i < pairs.size(); ++i)
      {
        if(!given_back[i]) { still.push_back(pairs[i]); continue; }
        parallel.prescribed_index[pairs[i].first] = own[pairs[i].first];
        parallel.prescribed_index[pairs[i].second] = own[pairs[i].second];
      }
      pairs.swap(still);
      if(pairs.empty())
      {
        answer = optimal_answer;
        return optimal;
      }
      result = compute_prescribed(parallel, answer, &doubtful);
    }
    result.number_of_cancelled_pairs = pairs.size();
    result.timings.setup_ms += optimal.timings.setup_ms;
    result.timings.factorization_ms += optimal.timings.factorization_ms;
    result.timings.solve_ms += optimal.timings.solve_ms;
    result.timings.total_ms += optimal.timings.total_ms;
    return result;
  }

  static bool follows_constraints(const Face_field_request& r)
  {
    return !r.feature_edges.empty() || std::find(r.constrained.begin(), r.constrained.end(), 1) != r.constrained.end() ||
           r.boundary != Boundary_alignment::NONE || r.alignment.lambda_given || r.alignment.weight_given;
  }

  // The singular pairs within the request's radius of a field that follows
  // constraints or its guidance (which no parallel field does) cancelled by
  // turning the field itself, the constrained faces kept (user manual,
  // section "Fields on Faces"; Turning_along_cuts). Where the turned field
  // shows other singularities than asked, read as any reader reads them,
  // the cancelled pair nearest each such vertex is given back and the field
  // turned again (a solve on the kept factor).
  Face_direction_field_result with_pairs_turned_away(const Face_field_request& request,
                                                     const Face_direction_field_result& optimal,
                                                     Face_field_answer& answer) const
  {
    const auto start = Clock::now();
    const std::vector<Complex> constraints = face_constraints(m_mesh, m_spaces, m_dual, request);
    std::vector<unsigned char> fixed(m_mesh.number_of_faces(), 0);
    for(std::size_t f = 0; f < fixed.size(); ++f) fixed[f] = constraints[f] != Complex(0., 0.);
    const std::vector<int>& own = answer.vertex_index;
    std::vector<Cut_pair> pairs =
      pairs_to_cut(m_mesh, fixed, request.cancellation_radius * bounding_box_diagonal(m_mesh), own);
    if(pairs.empty()) return optimal;
    const Turning_along_cuts turning(m_mesh, m_dual.weight, fixed);
    std::vector<double> theta(m_mesh.number_of_faces());
    for(std::size_t f = 0; f < theta.size(); ++f)
      theta[f] = static_cast<double>(request.degree) * angle_in_face(m_mesh, f, answer.directions[f]);
    Face_direction_field_result result;
    Face_field_answer turned;
    while(!pairs.empty())
    {
      result = without_singularities(optimal);
      write_answer(as_unit_powers(turning.turned(theta, cut_of(m_mesh, pairs))), request.degree, result, turned);
      std::vector<int> asked = own;
      for(const Cut_pair& pair : pairs) asked[pair.positive] = asked[pair.negative] = 0;
      if(turned.vertex_index == asked) break;
      give_back_pairs_near(asked, turned.vertex_index, pairs);
    }
    if(pairs.empty()) return optimal;
    answer = std::move(turned);
    result.number_of_cancelled_pairs = pairs.size();
    const double turning_ms = milliseconds_since(start);
    result.timings.solve_ms += turning_ms;
    result.timings.total_ms += turning_ms;
    return result;
  }

  // the pair nearest each vertex whose index is not the one asked, given back
  void give_back_pairs_near(const std::vector<int>& asked, const std::vector<int>& shown,
                            std::vector<Cut_pair>& pairs) const
  {
    std::vector<std::pair<std::size_t, std::size_t> > ends;
    for(const Cut_pair& pair : pairs) ends.emplace_back(pair.positive, pair.negative);
    std::vector<unsigned char> given_back(pairs.size(), 0);
    for(std::size_t v = 0; v < asked.size(); ++v)
      if(asked[v] != shown[v]) given_back[closest_pair(m_mesh, ends, v)] = 1;
    std::vector<Cut_pair> kept;
    for(std::size_t i = 0; i < pairs.size(); ++i)
      if(!given_back[i]) kept.push_back(std::move(pairs[i]));
    pairs.swap(kept);
  }

  static std::vector<Complex> as_unit_powers(const std::vector<double>& theta)
  {
    std::vector<Complex> u(theta.size());
    for(std::size_t f = 0; f < u.size(); ++f) u[f] = std::polar(1., theta[f]);
    return u;
  }

  // a result's report without its singular vertices, for write_answer() to count again
  static Face_direction_field_result without_singularities(Face_direction_field_result result)
  {
    result.index_sum = 0;
    result.number_of_singular_vertices = 0;
    for(Face_field_component_report& report : result.components)
      report.index_sum = 0, report.number_of_singular_vertices = 0;
    return result;
  }

  Face_direction_field_result compute_optimal(const Face_field_request& request, const SparseSolver* user_solver,
                                              Face_field_answer& answer) const
  {
    SparseSolver linear_solver = user_solver ? *user_solver : SparseSolver();
    const auto start = Clock::now();
    Face_direction_field_result result;
    result.degree = request.degree;
    result.mollification = m_spaces.mollification / m_length_scale;
    result.number_of_glued_edges = m_dual.number_of_glued_edges;
    Progress_report progress(request.progress);
    const Scoped_interruption_check interruption(progress.keep_going_test());  // asked during factorizations too
    progress.reached(0.);
    const std::vector<Complex> guidance = face_guidance(m_mesh, m_spaces, m_components, request);
    const std::vector<Complex> constraints = face_constraints(m_mesh, m_spaces, m_dual, request);
    Eigen_solve_options options;
    options.max_iterations = request.max_iterations;
    options.residual_tolerance = request.residual_tolerance;
    options.random_seed = request.random_seed;
    options.keep_going = progress.keep_going_within_step();
    options.transport_in_energy = true;
    std::vector<std::size_t> unknowns;
    for(const Component& comp : m_components.list) unknowns.push_back(comp.faces.size());
    Sequential_component_systems<SparseSolver> systems(std::move(unknowns), m_length_scale, user_solver);
    Alignment_request alignment = request.alignment;
    alignment.lambda = systems.eigenvalue_from_user(alignment.lambda);
    Component_fields<Sequential_component_systems<SparseSolver> > fields(systems, options, linear_solver, result.timings);
    std::vector<Complex> u(m_mesh.number_of_faces(), Complex(0., 0.));
    result.components.resize(m_components.list.size());
    result.timings.setup_ms = milliseconds_since(start);
    for(std::size_t c = 0; c < m_components.list.size(); ++c)
    {
      const double components = static_cast<double>(m_components.list.size());
      progress.reached(0.1 + 0.9 * static_cast<double>(c) / components,
                       0.1 + 0.9 * static_cast<double>(c + 1) / components);
      const Component& comp = m_components.list[c];
      const auto assembly_start = Clock::now();
      systems.set_matrices(c, face_energy_and_mass(m_mesh, m_spaces, m_dual, comp, request.degree,
                                                   local_face_numbers(comp, m_mesh.number_of_faces())));
      result.timings.setup_ms += milliseconds_since(assembly_start);
      Face_field_component_report& report = result.components[c];
      describe(comp, report);
      const Complex_vector x = solve_component(c, guidance, constraints, alignment, fields, report);
      for(std::size_t i = 0; i < comp.faces.size(); ++i) u[comp.faces[i]] = x[static_cast<Eigen::Index>(i)];
      if(report.eigenvalue) report.eigenvalue = systems.eigenvalue_to_user(*report.eigenvalue);
      report.lambda = systems.eigenvalue_to_user(report.lambda);
    }
    progress.reached(1.);
    write_answer(u, request.degree, result, answer);
    result.timings.total_ms = milliseconds_since(start);
    result.timings.solve_ms = result.timings.total_ms - result.timings.setup_ms - result.timings.factorization_ms;
    return result;
  }

  // The field with the prescribed vertex indices (user manual, section
  // "Fields on Faces"): the parallel section of the least changed dual
  // connection, each component turned as a whole towards its guidance and
  // constraints; the matching and the indices read from the change itself.
  // `doubtful_sides`, if given, receives a flag per side (corner) where the
  // matching is not, or only barely, the principal one.
  Face_direction_field_result compute_prescribed(const Face_field_request& request, Face_field_answer& answer,
                                                 std::vector<unsigned char>* doubtful_sides = nullptr) const
  {
    const auto start = Clock::now();
    Face_direction_field_result result;
    result.degree = request.degree;
    result.mollification = m_spaces.mollification / m_length_scale;
    result.prescribed = true;
    result.components.resize(m_components.list.size());
    for(std::size_t c = 0; c < m_components.list.size(); ++c)
    {
      describe(m_components.list[c], result.components[c]);
      result.components[c].solve = Field_solve::PARALLEL_SECTION;
      result.components[c].converged = true;
    }
    check_face_prescription(request, result.components);
    Progress_report progress(request.progress);
    const Scoped_interruption_check interruption(progress.keep_going_test());  // asked during factorizations too
    progress.reached(0.);
    // the trees and the factored Laplacian of the faces, kept for the next prescription
    std::lock_guard<std::mutex> exclusive(m_change_mutex);
    if(!m_change)
    {
      m_change = std::make_unique<Face_connection_change>(m_mesh, m_spaces, m_dual, m_components);
      result.timings.factorization_ms = milliseconds_since(start);
    }
    Face_connection_change& change = *m_change;
    const Dual_trees& trees = change.trees();
    result.timings.setup_ms = milliseconds_since(start) - result.timings.factorization_ms;
    Eigen::VectorXd delta;
    if(!change.solve(request.prescribed_index, request.degree, delta))
      throw Invalid_input_error("prescribed_singularities asks the field to turn by half a turn or more across "
                                "an edge (indices too large for the valence of their vertices, or too close "
                                "together): no direction per face with a matching can show it; spread the "
                                "singularities out");

    std::vector<double> theta = change.parallel_angles(delta);
    turn_towards_guidance(request, theta);
    progress.reached(1.);
    const auto rotation = [&](std::size_t side) { return change_across(trees, delta, side); };
    std::vector<unsigned char> non_principal(3 * m_mesh.number_of_faces(), 0);  // flagged in parallel, then counted
    parallel_for_each_index(non_principal.size(), [&](std::size_t side) {
      non_principal[side] =
        m_mesh.twin_corner[side] != no_index && is_representative_side(m_mesh, side) &&
        std::abs(rotation(side) - face_rotation(theta, m_dual, request.degree, side, m_mesh.twin_corner[side])) > 1e-6;
    });
    for(unsigned char flag : non_principal) result.number_of_non_principal_jumps += flag;
    if(doubtful_sides) flag_doubtful_sides(theta, request.degree, non_principal, *doubtful_sides);
    write_turning(theta, turning_of_field(m_mesh, m_spaces, m_dual, m_components, theta, request.degree, rotation),
                  request.degree, result, answer);
    result.timings.total_ms = milliseconds_since(start);
    result.timings.solve_ms = result.timings.total_ms - result.timings.setup_ms - result.timings.factorization_ms;
    return result;
  }

  // The sides where the matching is not the principal one, and those where
  // the field turns by so nearly pi/n that a reader recomputing the matching
  // in its own arithmetic may choose the other one.
  void flag_doubtful_sides(const std::vector<double>& theta, int n, const std::vector<unsigned char>& non_principal,
                           std::vector<unsigned char>& doubtful) const
  {
    const double margin = 0.05;  // of the n-th power's turn: far above rounding, far below a smooth field's turns
    doubtful.assign(non_principal.size(), 0);
    parallel_for_each_index(doubtful.size(), [&](std::size_t side) {
      const std::size_t twin = m_mesh.twin_corner[side];
      doubtful[side] = non_principal[side] ||
                       (twin != no_index && is_representative_side(m_mesh, side) &&
                        std::abs(face_rotation(theta, m_dual, n, side, twin)) > CGAL_PI - margin);
    });
  }

  // Only interior vertices have an index, and a closed component's indices
  // add up to n chi (Poincare-Hopf); every other assignment is shown.
  void check_face_prescription(const Face_field_request& request,
                               const std::vector<Face_field_component_report>& reports) const
  {
    if(request.alignment.lambda_given || request.alignment.weight_given)
      throw Invalid_input_error("alignment_lambda and alignment_weight do not apply with prescribed_singularities "
                                "(the field is turned as a whole towards the guidance)");
    const std::vector<int>& k = request.prescribed_index;
    for(std::size_t v = 0; v < k.size(); ++v)
    {
      if(k[v] == 0) continue;
      if(m_mesh.fan_size(v) == 0)
        throw Invalid_input_error("prescribed_singularities names vertex " + std::to_string(v) +
                                  ", which belongs to no face");
      if(m_mesh.is_border_vertex[v])
        throw Invalid_input_error("prescribed_singularities names vertex " + std::to_string(v) + " on the boundary, "
                                  "where a field on faces has no index (the boundary's turning is the component's "
                                  "boundary_index)");
    }
    for(std::size_t c = 0; c < reports.size(); ++c)
    {
      if(!reports[c].is_closed) continue;
      long long sum = 0;
      for(std::size_t v : m_components.list[c].vertices) sum += k[v];
      check_index_sum(c, sum, request.degree, reports[c].euler_characteristic);
    }
  }

  // Each component's field turned by the angle that best matches its
  // guidance and constraints (n-th powers, weighted by the face areas).
  void turn_towards_guidance(const Face_field_request& request, std::vector<double>& theta) const
  {
    const std::vector<Complex> guidance = face_guidance(m_mesh, m_spaces, m_components, request);
    const std::vector<Complex> constraints = face_constraints(m_mesh, m_spaces, m_dual, request);
    for(const Component& comp : m_components.list)
    {
      Complex sum(0., 0.);
      for(std::size_t f : comp.faces)
        sum += m_spaces.face_area[f] * (guidance[f] + constraints[f]) * std::polar(1., -theta[f]);
      if(std::abs(sum) == 0.) continue;
      const double turn = std::arg(sum);
      for(std::size_t f : comp.faces) theta[f] = reduce_angle(theta[f] + turn);
    }
  }

  // Component c's field (Component_fields: as on vertices, with A and M of
  // the faces) for its share of the guidance and constraints.
  Complex_vector solve_component(std::size_t c, const std::vector<Complex>& guidance,
                                 const std::vector<Complex>& constraint_values, const Alignment_request& alignment,
                                 Component_fields<Sequential_component_systems<SparseSolver> >& fields,
                                 Face_field_component_report& report) const
  {
    const Component& comp = m_components.list[c];
    const Eigen::Index nf = static_cast<Eigen::Index>(comp.faces.size());
    Complex_vector q(nf);
    Constraints constraints;
    constraints.is_constrained.assign(comp.faces.size(), 0);
    constraints.values = Complex_vector::Zero(nf);
    for(Eigen::Index i = 0; i < nf; ++i)
    {
      const std::size_t f = comp.faces[static_cast<std::size_t>(i)];
      q[i] = guidance[f];
      constraints.is_constrained[static_cast<std::size_t>(i)] = constraint_values[f] != Complex(0., 0.);
      constraints.values[i] = constraint_values[f];
    }
    if(nf > 1) return fields.field_of(c, q, constraints, alignment, report);
    // a lone face has no energy: its constraint, its guidance, or its first side
    const bool constrained = !constraints.empty(), aligned = q[0] != Complex(0., 0.);
    report.solve = aligned || constrained ? Field_solve::LINEAR_SOLVE : Field_solve::EIGEN_SOLVE;
    report.eigenvalue = 0.;
    report.converged = true;
    const Complex value = constrained ? constraints.values[0] : aligned ? q[0] : Complex(1., 0.);
    return Complex_vector::Constant(1, value / std::abs(value));
  }

  void describe(const Component& comp, Face_field_component_report& report) const
  {
    std::size_t border_sides = 0;
    for(std::size_t f : comp.faces)
      for(int c = 0; c < 3; ++c) border_sides += m_mesh.twin_corner[3 * f + static_cast<std::size_t>(c)] == no_index;
    const std::size_t edges = (3 * comp.faces.size() + border_sides) / 2;
    report.number_of_vertices = comp.vertices.size();
    report.number_of_faces = comp.faces.size();
    report.euler_characteristic = static_cast<int>(static_cast<long long>(comp.vertices.size()) -
                                                   static_cast<long long>(edges) +
                                                   static_cast<long long>(comp.faces.size()));
    report.is_closed = border_sides == 0;
  }

  void write_answer(const std::vector<Complex>& u, int n, Face_direction_field_result& result,
                    Face_field_answer& answer) const
  {
    std::vector<double> theta(u.size());
    for(std::size_t f = 0; f < u.size(); ++f) theta[f] = std::arg(u[f]);
    write_turning(theta, face_field_turning(m_mesh, m_spaces, m_dual, m_components, u, n), n, result, answer);
  }

  void write_turning(const std::vector<double>& theta, const Face_field_turning& turning, int n,
                     Face_direction_field_result& result, Face_field_answer& answer) const
  {
    answer.directions.resize(theta.size());
    parallel_for_each_index(theta.size(), [&](std::size_t f) {
      answer.directions[f] = direction_in_face(m_mesh, f, theta[f] / static_cast<double>(n));
    });
    for(std::size_t v = 0; v < m_mesh.number_of_vertices(); ++v)
    {
      if(turning.vertex_index[v] == 0) continue;
      Face_field_component_report& report =
        result.components[m_components.component_of_face[m_mesh.fan_corners[m_mesh.fan_offsets[v]] / 3]];
      report.index_sum += turning.vertex_index[v];
      ++report.number_of_singular_vertices;
    }
    for(std::size_t c = 0; c < result.components.size(); ++c)
    {
      Face_field_component_report& report = result.components[c];
      report.boundary_index = turning.boundary_index[c];
      result.index_sum += report.index_sum;
      result.number_of_singular_vertices += report.number_of_singular_vertices;
      result.iterations = (std::max)(result.iterations, report.iterations);
      result.residual = (std::max)(result.residual, report.residual);
      result.converged = result.converged && report.converged;
    }
    answer.vertex_index = turning.vertex_index;
    answer.matching = turning.matching;
  }

  Indexed_mesh m_mesh;
  double m_length_scale = 1.;
  Components m_components;
  Tangent_spaces m_spaces;
  Dual_connection m_dual;
  mutable std::mutex m_change_mutex;
  mutable std::unique_ptr<Face_connection_change> m_change;  // made by the first prescription
};

template <typename SparseSolver>
Face_field_engine<SparseSolver>::Face_field_engine(Indexed_mesh mesh, double mollification,
                                                   std::vector<std::size_t> point_of_vertex)
  : m_impl(new Impl(std::move(mesh), mollification, point_of_vertex))
{
}

template <typename SparseSolver>
Face_field_engine<SparseSolver>::~Face_field_engine() = default;

template <typename SparseSolver>
Face_direction_field_result Face_field_engine<SparseSolver>::compute(const Face_field_request& request,
                                                                     const SparseSolver* solver,
                                                                     Face_field_answer& answer) const
{
  return m_impl->compute(request, solver, answer);
}

template <typename SparseSolver>
const Indexed_mesh& Face_field_engine<SparseSolver>::mesh() const
{
  return m_impl->mesh();
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FACE_FIELD_ENGINE_IMPL_H
