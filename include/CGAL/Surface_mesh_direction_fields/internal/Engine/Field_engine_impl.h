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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FIELD_ENGINE_IMPL_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FIELD_ENGINE_IMPL_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Field_engine.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
// the engine's parts: the mesh's geometry, the systems of each component, the
// field of one component, prescribed singularities
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/component_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/component_systems.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/field_targets.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/mesh_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/prescribed_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/progress_report.h>
// the method's last steps: guidance, indices, directions in 3D
#include <CGAL/Surface_mesh_direction_fields/internal/Method/extrinsic_directions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_inputs.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/singularities.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <memory>
#include <utility>
#include <vector>

// The definitions of Field_engine (Field_engine.h): compute() as its named
// steps over the parts of this folder.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename SparseSolver>
class Field_engine<SparseSolver>::Impl
{
  typedef std::complex<double> Complex;
  typedef std::chrono::steady_clock Clock;

public:
  Impl(Indexed_mesh mesh, double mollification, std::vector<Vec3> normals)
    : m_geometry(std::move(mesh), mollification, std::move(normals)), m_prescribed(m_geometry)
  {}

  // One field (see Globally_optimal_direction_field::compute()), on the
  // kept systems under this call's solver and backend.
  Direction_field_result compute(const Field_request& request, const SparseSolver* given_solver, Field_answer& answer)
  {
    const auto start = Clock::now();
    Direction_field_result result = empty_result(request);
    if(request.prescribed) return compute_prescribed(request, given_solver, std::move(result), start, answer);
    Component_systems<SparseSolver> systems(m_geometry, m_kept, {given_solver, request.distributed});
    try
    {
      return compute_optimal(request, given_solver, systems, std::move(result), start, answer);
    }
    catch(...)
    {
      systems.forget_after_failure();  // the next call starts from a consistent state
      throw;
    }
  }

  std::vector<Corner_loop> prescription_loops() { return m_prescribed.loops(); }

private:
  // The smallest or aligned field: compute()'s steps.
  Direction_field_result compute_optimal(const Field_request& request, const SparseSolver* given_solver,
                                         Component_systems<SparseSolver>& systems, Direction_field_result result,
                                         Clock::time_point start, Field_answer& answer)
  {
    SparseSolver linear_solver = given_solver != nullptr ? *given_solver : SparseSolver();
    Progress_report progress(request.progress);
    const Scoped_interruption_check interruption(progress.keep_going_test());  // asked during factorizations too
    progress.reached(0.);

    // 1. the hard constraints and the alignment request (manual, "Aligned and Constrained Fields")
    Field_targets targets = field_targets(m_geometry, request);
    const std::vector<std::size_t> early = factored_before_guidance(systems, targets);

    // 2. the connection of degree n and the matrices of (n, s), unless kept from the last call
    systems.update_matrices(result.degree, result.smoothness_parameter, systems.shift_only(early, targets.alignment.lambda));
    result.timings.setup_ms = milliseconds_since(start);
    progress.reached(0.1);

    // 3. the guidance q, computed while the factorizations that do not depend on it run
    read_guidance(request, early, systems, linear_solver, targets, result.timings);
    progress.reached(0.2);

    // 4. one problem per component: the smallest eigenvector, or the aligned / constrained solve
    Eigen_solve_options options = eigen_solve_options(request);
    options.keep_going = progress.keep_going_within_step();
    Component_fields<Component_systems<SparseSolver> > fields(systems, options, linear_solver, result.timings);
    std::vector<Complex> u(m_geometry.mesh.number_of_vertices(), Complex(0., 0.));
    answer.magnitudes.assign(u.size(), 0.);
    result.components.resize(m_geometry.components.list.size());
    for(std::size_t c = 0; c < result.components.size(); ++c)
    {
      const double components = static_cast<double>(result.components.size());
      progress.reached(0.2 + 0.8 * static_cast<double>(c) / components,
                       0.2 + 0.8 * static_cast<double>(c + 1) / components);
      solve_component(c, fields, targets, options, result, u, answer.magnitudes);
    }
    progress.reached(1.);

    // 5. the outputs: singular faces with their indices, unit directions in 3D
    report_indices(face_indices(m_geometry.mesh, systems.connection(), u), result, answer);
    result.loop_turns = m_prescribed.loop_turns_of(u, systems.connection(), result.components);
    write_directions(u, result.degree, targets.constraints, result, answer);
    store_coefficients(std::move(u), answer);
    for(Component_report& report : result.components)
    {
      if(report.eigenvalue) report.eigenvalue = m_geometry.eigenvalue_to_user(*report.eigenvalue);
      report.lambda = m_geometry.eigenvalue_to_user(report.lambda);
    }
    finish_timings(start, result.timings);
    return result;
  }

public:
  // A and M of every component, gathered into matrices over all vertices.
  std::pair<Complex_sparse_matrix, Complex_sparse_matrix> energy_and_mass(int degree, double s)
  {
    const Mesh_geometry& g = m_geometry;
    const Connection& connection = m_kept.connection_of_degree(m_geometry, degree);
    const std::vector<Energy_and_mass> parts =
      assemble_energy_and_mass(g.mesh, g.tangent_spaces, connection, g.components, s);
    // lengths were multiplied by length_scale: A is unchanged, areas are divided back
    const double area_to_user = 1. / (g.length_scale * g.length_scale);
    const Eigen::Index nv = static_cast<Eigen::Index>(g.mesh.number_of_vertices());
    std::pair<Complex_sparse_matrix, Complex_sparse_matrix> whole(Complex_sparse_matrix(nv, nv),
                                                                   Complex_sparse_matrix(nv, nv));
    std::vector<Eigen::Triplet<Complex> > energy, mass;
    for(std::size_t c = 0; c < parts.size(); ++c)
    {
      const std::vector<Compact_index>& vertex = g.components.list[c].vertices;
      auto gather = [&](const Complex_sparse_matrix& part, double factor,
                        std::vector<Eigen::Triplet<Complex> >& out) {
        for(Eigen::Index j = 0; j < part.outerSize(); ++j)
          for(Complex_sparse_matrix::InnerIterator it(part, j); it; ++it)
            out.emplace_back(static_cast<Eigen::Index>(vertex[static_cast<std::size_t>(it.row())]),
                             static_cast<Eigen::Index>(vertex[static_cast<std::size_t>(it.col())]),
                             factor * it.value());
      };
      gather(parts[c].energy, 1., energy);
      gather(parts[c].mass, area_to_user, mass);
    }
    whole.first.setFromTriplets(energy.begin(), energy.end());
    whole.second.setFromTriplets(mass.begin(), mass.end());
    return whole;
  }
  void keep_factorizations(bool keep) { m_kept.keep_factorizations = keep; }
  const Indexed_mesh& mesh() const { return m_geometry.mesh; }

private:
  Direction_field_result empty_result(const Field_request& request) const
  {
    Direction_field_result result;
    result.degree = request.degree;
    result.smoothness_parameter = request.s;
    result.mollification = m_geometry.tangent_spaces.mollification / m_geometry.length_scale;
    result.tangent_plane_vertices = m_geometry.tangent_plane_vertices;
    return result;
  }

  static void finish_timings(Clock::time_point start, Direction_field_timings& timings)
  {
    timings.total_ms = milliseconds_since(start);
    timings.solve_ms = timings.total_ms - timings.setup_ms - timings.factorization_ms;
  }

  static Eigen_solve_options eigen_solve_options(const Field_request& request)
  {
    Eigen_solve_options options;
    options.max_iterations = request.max_iterations;
    options.residual_tolerance = request.residual_tolerance;
    options.random_seed = request.random_seed;
    options.shift_fraction = shift_fraction_for(request.s);
    return options;
  }

  // u as the user sees it: the phase of the solution, the length of `magnitudes`
  // (per component, the solution times one factor: still an eigenvector of A, M).
  static void store_coefficients(std::vector<Complex>&& u, Field_answer& answer)
  {
    answer.coefficients = std::move(u);
    for(std::size_t v = 0; v < answer.coefficients.size(); ++v)
    {
      Complex& c = answer.coefficients[v];
      const double length = std::abs(c);
      c = length > 0. ? c * (answer.magnitudes[v] / length) : Complex(0., 0.);
    }
  }

  // The field of component c into u and `magnitudes`; its report into result.components[c].
  void solve_component(std::size_t c, Component_fields<Component_systems<SparseSolver> >& fields,
                       const Field_targets& targets,
                       const Eigen_solve_options& options, Direction_field_result& result, std::vector<Complex>& u,
                       std::vector<double>& magnitudes) const
  {
    const Component& comp = m_geometry.components.list[c];
    Component_report& report = result.components[c];
    describe_component(m_geometry.mesh, comp, report);
    const Complex_vector field = fields.field_of(c, component_guidance(comp, targets.guidance),
                                                 component_constraints(comp, targets.constraints), targets.alignment,
                                                 report);
    // a solver that fails without saying so (a user's, or a library's out of
    // memory) must not turn into NaN directions in the outputs
    if(!field.allFinite() || field.size() != static_cast<Eigen::Index>(comp.vertices.size()))
      throw Solver_failure_error("the solver returned a field that is not finite on component " + std::to_string(c));
    report.low_magnitude_fraction = fraction_below(field, low_magnitude_threshold(options.residual_tolerance));
    const double root_area = std::sqrt(m_geometry.area_of(c));
    for(std::size_t i = 0; i < comp.vertices.size(); ++i)
    {
      u[comp.vertices[i]] = field[static_cast<Eigen::Index>(i)];
      magnitudes[comp.vertices[i]] = std::abs(field[static_cast<Eigen::Index>(i)]) * root_area;
    }
    result.iterations = (std::max)(result.iterations, report.iterations);
    result.residual = (std::max)(result.residual, report.residual);
    result.converged = result.converged && report.converged;
  }

  // compute() with prescribed singularities (manual, "Placing Singularities"):
  // the least change of the connection that makes it flat with the given
  // holonomies, then its parallel section, rotated per component to follow
  // the guidance or a constrained vertex.
  Direction_field_result compute_prescribed(const Field_request& request, const SparseSolver* given_solver,
                                            Direction_field_result result, Clock::time_point start,
                                            Field_answer& answer)
  {
    Progress_report progress(request.progress);
    const Scoped_interruption_check interruption(progress.keep_going_test());
    progress.reached(0.);
    Field_targets targets = field_targets(m_geometry, request);
    Prescribed_fields::refuse_other_requests(request);
    const Connection& connection = m_kept.connection_of_degree(m_geometry, result.degree);
    result.timings.setup_ms = milliseconds_since(start);
    result.components.resize(m_geometry.components.list.size());
    for(std::size_t c = 0; c < result.components.size(); ++c)
    {
      describe_component(m_geometry.mesh, m_geometry.components.list[c], result.components[c]);
      result.components[c].solve = Field_solve::PARALLEL_SECTION;
      result.components[c].converged = true;
    }
    std::vector<Complex> u = m_prescribed.field(request, connection, result);
    result.prescribed = true;
    SparseSolver linear_solver = given_solver != nullptr ? *given_solver : SparseSolver();
    Component_systems<SparseSolver> systems(m_geometry, m_kept, {given_solver, nullptr});
    read_guidance(request, {}, systems, linear_solver, targets, result.timings);
    for(std::size_t c = 0; c < result.components.size(); ++c) m_prescribed.rotate(c, targets, u);
    report_indices(m_prescribed.checked_indices(request, connection, u), result, answer);
    result.loop_turns = m_prescribed.turns_of_prescribed(u, connection);
    write_directions(u, result.degree, targets.constraints, result, answer);
    answer.magnitudes.resize(u.size());
    for(std::size_t v = 0; v < u.size(); ++v) answer.magnitudes[v] = std::abs(u[v]);  // 1, 0 at isolated vertices
    store_coefficients(std::move(u), answer);
    progress.reached(1.);
    finish_timings(start, result.timings);
    return result;
  }

  // targets.guidance, computed while the factorizations that do not depend
  // on it run (counted as factorization time); after them when the guidance
  // factors a matrix of its own (the Hopf differential's estimate): two
  // factorizations side by side would make OpenBLAS's number of threads at
  // the top of each elimination tree, and with it the last digits, depend on
  // their timing (Single_threaded_blas in dense_kernels.h).
  void read_guidance(const Field_request& request, const std::vector<std::size_t>& early,
                     Component_systems<SparseSolver>& systems, SparseSolver& linear_solver, Field_targets& targets,
                     Direction_field_timings& timings)
  {
    auto compute_guidance = [&] {
      targets.guidance = guidance_coefficients(m_geometry.mesh, m_geometry.tangent_spaces, m_geometry.components,
                                               request, m_geometry.normals, linear_solver);
    };
    auto factor_early = [&] {
      for(std::size_t c : early) systems.factor_aligned_system(c, targets.alignment.lambda);
    };
    const bool guidance_factors = request.curvature != Principal_curvature_alignment::NONE &&
                                  request.curvature_estimate == Principal_curvature_estimate::HOPF_DIFFERENTIAL;
    if(early.empty() || guidance_factors)
    {
      compute_guidance();
      if(early.empty()) return;
    }
    const auto start = Clock::now();
    if(guidance_factors)
    {
      systems.prepare_mass_operator();
      factor_early();
    }
    else
      parallel_invoke([&] { compute_guidance(); systems.prepare_mass_operator(); }, factor_early);
    timings.factorization_ms += milliseconds_since(start);
  }

  // The components whose aligned system A - lambda_t M is known before the
  // guidance: lambda_t given or the default 0, no constraint, nothing that
  // needs lambda_1 first, a solver that certifies definiteness. (If the
  // guidance then vanishes on a component, its field is the smoothest one and
  // this factorization is not used.)
  std::vector<std::size_t> factored_before_guidance(const Component_systems<SparseSolver>& systems,
                                                    const Field_targets& targets) const
  {
    std::vector<std::size_t> early;
    if(!targets.has_guidance || systems.user_solver() || targets.alignment.weight_given ||
       targets.alignment.eigenvalue_bound)
      return early;
    for(std::size_t c = 0; c < m_geometry.components.list.size(); ++c)
      if(systems.certifies_definiteness(c) &&
         component_constraints(m_geometry.components.list[c], targets.constraints).empty())
        early.push_back(c);
    return early;
  }

  // The faces of non-zero index and the index sums (manual, "Singularities").
  void report_indices(const std::vector<int>& index, Direction_field_result& result, Field_answer& answer) const
  {
    for(std::size_t f = 0; f < m_geometry.mesh.number_of_faces(); ++f)
    {
      Component_report& report = result.components[m_geometry.components.component_of_face[f]];
      report.index_sum += index[f];
      result.index_sum += index[f];
      if(index[f] != 0)
      {
        ++report.number_of_singular_faces;
        ++result.number_of_singular_faces;
        answer.singular_faces.emplace_back(f, index[f]);
      }
    }
  }

  // The unit 3D direction of every vertex (in parallel).
  void write_directions(const std::vector<Complex>& u, int degree, const Vertex_constraints& constraints,
                        Direction_field_result& result, Field_answer& answer) const
  {
    const Mesh_geometry& g = m_geometry;
    std::vector<Vec3>& directions = answer.directions;
    directions.resize(g.mesh.number_of_vertices());
    parallel_for_each_index(directions.size(), [&](std::size_t i) {
      directions[i] = tangent_direction(g.mesh, g.tangent_spaces, i, u[i], degree, g.normals[i]);
      // a prescribed direction exactly (see Vertex_constraints::shown)
      if(!constraints.shown.empty() && constraints.is_constrained[i] && norm(constraints.shown[i]) > 0.)
        directions[i] = constraints.shown[i];
    });
    for(std::size_t i = 0; i < directions.size(); ++i)
      if(g.mesh.fan_size(i) == 0) ++result.number_of_isolated_vertices;
  }

  Mesh_geometry m_geometry;                   // constant after construction
  Kept_systems<SparseSolver> m_kept;          // the matrices and factorizations of (n, s)
  Prescribed_fields m_prescribed;             // the cycle basis and the vertex Laplacian, when first needed
};

template <typename SparseSolver>
Field_engine<SparseSolver>::Field_engine(Indexed_mesh mesh, double mollification, std::vector<Vec3> normals)
  : m_impl(std::make_unique<Impl>(std::move(mesh), mollification, std::move(normals)))
{}

template <typename SparseSolver>
Field_engine<SparseSolver>::~Field_engine() = default;

template <typename SparseSolver>
Direction_field_result Field_engine<SparseSolver>::compute(const Field_request& request, const SparseSolver* solver,
                                                           Field_answer& answer)
{
  return m_impl->compute(request, solver, answer);
}

template <typename SparseSolver>
std::vector<Corner_loop> Field_engine<SparseSolver>::prescription_loops()
{
  return m_impl->prescription_loops();
}

template <typename SparseSolver>
std::pair<Complex_sparse_matrix, Complex_sparse_matrix> Field_engine<SparseSolver>::energy_and_mass(int degree,
                                                                                                    double s)
{
  return m_impl->energy_and_mass(degree, s);
}

template <typename SparseSolver>
void Field_engine<SparseSolver>::keep_factorizations(bool keep)
{
  m_impl->keep_factorizations(keep);
}

template <typename SparseSolver>
std::size_t Field_engine<SparseSolver>::number_of_vertices() const
{
  return m_impl->mesh().number_of_vertices();
}

template <typename SparseSolver>
std::size_t Field_engine<SparseSolver>::number_of_faces() const
{
  return m_impl->mesh().number_of_faces();
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FIELD_ENGINE_IMPL_H
