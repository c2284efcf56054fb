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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_ENGINE_IMPL_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_ENGINE_IMPL_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Field_engine.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
// the mesh's components, and the request's guidance and constraints in the tangent spaces
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/field_inputs.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
// the method: tangent spaces -> connection -> local matrices -> A, M -> directions, indices
#include <CGAL/Surface_mesh_direction_fields/internal/Method/assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/distributed_backend.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/extrinsic_directions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/folded_fans.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/guidance.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/mass_operator.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/prescribed_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/singularities.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
// the linear algebra: factorizations, the eigen-solve, the linear solves
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

// The definitions of Field_engine (Field_engine.h): everything between the
// indexed mesh with the request of the named parameters and the directions,
// magnitudes and singular faces by index.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename SparseSolver>
class Field_engine<SparseSolver>::Impl
{
  typedef std::complex<double> Complex;
  typedef std::chrono::steady_clock Clock;

  // A solver and its factorization, for one component's A + shift M: its
  // symbolic analysis is reused for every later factorization (the pattern
  // of A + shift M does not depend on n, s or the shift); `aligned_lambda`
  // is the lambda_t of the aligned system it holds (NaN: it holds another
  // matrix), so that another guidance field with the same lambda_t costs
  // one solve.
  struct Component_factorization
  {
    SparseSolver solver;
    Factored_matrix<SparseSolver> factored{solver};
    bool analyzed = false;
    double aligned_lambda = std::numeric_limits<double>::quiet_NaN();
    double indefinite_lambda = std::numeric_limits<double>::quiet_NaN();  // the last lambda_t found too large
  };
  static constexpr bool detects_indefinite = Factored_matrix<SparseSolver>::detects_indefinite;

public:
  // The mesh work: intrinsic geometry (the rescaled tangent spaces), the
  // components, the vertex normals and the layout at folded triangles.
  Impl(Indexed_mesh mesh, double mollification, std::vector<Vec3> normals)
    : m_mesh(std::move(mesh)), m_normals(std::move(normals))
  {
    m_length_scale = normalize_coordinates(m_mesh);
    const bool default_normals = m_normals.empty();
    // The components (a sequential breadth-first search) on one thread, while
    // the other computes the tangent spaces and the normals.
    auto find_components = [&] { m_components = split_into_components(m_mesh); };
    auto compute_tangent_planes = [&] {
      m_tangent_spaces = compute_tangent_spaces(m_mesh, mollification);
      // the tangent planes of the outputs and of the guidance vectors
      if(default_normals) m_normals = angle_weighted_vertex_normals(m_mesh, m_tangent_spaces);
      m_tangent_plane_vertices = lay_out_folded_fans(m_mesh, m_normals, default_normals, m_tangent_spaces);
    };
    parallel_invoke(find_components, compute_tangent_planes);
    check_components_have_area(m_mesh, m_components, m_tangent_spaces.mollification);
  }

  // One field (see Globally_optimal_direction_field::compute()).
  Direction_field_result compute(const Field_request& request, const SparseSolver* given_solver, Field_answer& answer)
  {
    const auto start = Clock::now();
    Direction_field_result result;
    result.degree = request.degree;
    result.smoothness_parameter = request.s;
    result.mollification = m_tangent_spaces.mollification / m_length_scale;
    result.tangent_plane_vertices = m_tangent_plane_vertices;
    if(request.prescribed) return compute_prescribed(request, given_solver, std::move(result), start, answer);
    const Eigen_solve_options options = eigen_solve_options(request);

    // A solver given as a named parameter is used for this call only, without reuse.
    const bool user_solver = given_solver != nullptr;
    SparseSolver linear_solver = user_solver ? *given_solver : SparseSolver();
    m_user_solver = user_solver ? std::make_unique<Component_factorization>() : nullptr;
    if(user_solver) m_user_solver->solver = linear_solver;
    // A backend over several processes (Petsc_distributed_solver) for this call.
    m_distributed = request.distributed;

    // 1. the hard constraints and the alignment request (manual, "Aligned and Constrained Fields")
    Field_targets targets = field_targets(request);
    targets.alignment.lambda = eigenvalue_from_user(targets.alignment.lambda);
    const std::vector<std::size_t> early = factored_before_guidance(targets, user_solver);

    // 2. the connection of degree n and the matrices of (n, s), unless kept from the last call
    update_matrices(result.degree, result.smoothness_parameter, shift_only(early, targets.alignment.lambda));
    result.timings.setup_ms = milliseconds_since(start);

    // 3. the guidance q, computed while the factorizations that do not depend on it run
    read_guidance(request, early, linear_solver, targets, result.timings);

    // 4. one problem per component: the smallest eigenvector, or the aligned / constrained solve
    Vertex_field field(m_mesh.number_of_vertices());
    result.components.resize(m_components.list.size());
    for(std::size_t c = 0; c < m_components.list.size(); ++c)
    {
      solve_component(c, targets, options, user_solver, linear_solver, result, field);
      const Component_report& report = result.components[c];
      result.iterations = (std::max)(result.iterations, report.iterations);
      result.residual = (std::max)(result.residual, report.residual);
      result.converged = result.converged && report.converged;
    }

    // 5. the outputs: singular faces with their indices, unit directions in 3D, magnitudes
    report_indices(face_indices(m_mesh, m_connection, field.coefficients), result, answer);
    result.loop_turns = loop_turns_of(field.coefficients, result.degree, result.components);
    write_directions(field.coefficients, result.degree, targets.constraints, result, answer);
    answer.magnitudes = std::move(field.magnitudes);

    for(Component_report& report : result.components)
    {
      report.eigenvalue = eigenvalue_to_user(report.eigenvalue);
      report.lambda = eigenvalue_to_user(report.lambda);
    }
    result.timings.total_ms = milliseconds_since(start);
    result.timings.solve_ms = result.timings.total_ms - result.timings.setup_ms - result.timings.factorization_ms;
    if(!m_keep_factorizations) m_factorizations.clear();
    m_shifted_lower.clear();
    m_mass_operator.reset();
    m_user_solver.reset();
    m_distributed = nullptr;
    return result;
  }

  // The loops of prescription_loops(), by corner and direction.
  std::vector<Corner_loop> prescription_loops()
  {
    prepare_adjustment();
    std::vector<Corner_loop> loops(m_adjustment->number_of_loops());
    const Edge_numbering& edges = m_adjustment->edges();
    for(std::size_t l = 0; l < loops.size(); ++l)
    {
      const Edge_cycle& loop = m_adjustment->loop(l);
      for(std::size_t i = 0; i < loop.edges.size(); ++i)
        loops[l].emplace_back(edges.corner_of_edge[loop.edges[i]], loop.signs[i] > 0 ? 1 : -1);
    }
    return loops;
  }

  void keep_factorizations(bool keep) { m_keep_factorizations = keep; }
  const Indexed_mesh& mesh() const { return m_mesh; }

private:
  // The field being built: a coefficient and a magnitude per vertex.
  struct Vertex_field
  {
    explicit Vertex_field(std::size_t n) : coefficients(n, Complex(0., 0.)), magnitudes(n, 0.) {}
    std::vector<Complex> coefficients;
    std::vector<double> magnitudes;
  };

  // What the field must follow: the guidance and the constraints as coefficients.
  struct Field_targets
  {
    std::vector<Complex> guidance;  // q per vertex, before normalization; empty: none
    bool has_guidance = false;      // whether the named parameters ask for one
    Vertex_constraints constraints;
    Alignment_request alignment;
  };

  // compute() with prescribed singularities (manual, "Placing Singularities"):
  // the least change of the connection that makes it flat with the given
  // holonomies, then its parallel section, rotated per component to follow
  // the guidance or a constrained vertex.
  Direction_field_result compute_prescribed(const Field_request& request, const SparseSolver* given_solver,
                                            Direction_field_result result, Clock::time_point start,
                                            Field_answer& answer)
  {
    Field_targets targets = field_targets(request);
    refuse_with_prescription(request, targets);
    update_connection(result.degree);
    result.timings.setup_ms = milliseconds_since(start);
    prepare_adjustment();
    if(!m_adjustment->is_factored())  // once per mesh: the factored vertex Laplacian
    {
      const auto factor_start = Clock::now();
      m_adjustment->factor(m_mesh, m_tangent_spaces);
      result.timings.factorization_ms = milliseconds_since(factor_start);
    }
    const std::vector<int>& k = request.prescribed_index;
    const Loop_turns turns = prescribed_turns(request.loop_turns);
    result.components.resize(m_components.list.size());
    for(std::size_t c = 0; c < m_components.list.size(); ++c)
    {
      describe_component(m_mesh, m_components.list[c], result.components[c]);
      result.components[c].eigenvalue = std::numeric_limits<double>::quiet_NaN();
      result.components[c].converged = true;
    }
    check_prescription(m_mesh, m_components, m_connection, result.components, k);

    const Eigen::VectorXd& rho = transport_angles(result.degree);
    const Eigen::VectorXd x = m_adjustment->solve(m_mesh, m_connection, rho, k, turns.turns);
    check_free_loops(rho, x, turns);
    result.prescribed = true;
    result.holonomy_error = m_adjustment->holonomy_error(m_connection, rho, x, k);
    std::vector<Complex> u = parallel_section(m_adjustment->cycle_basis(), m_mesh.number_of_vertices(), rho, x);
    SparseSolver linear_solver = given_solver != nullptr ? *given_solver : SparseSolver();
    read_guidance(request, {}, linear_solver, targets, result.timings);
    for(std::size_t c = 0; c < m_components.list.size(); ++c) rotate_component(c, targets, u);
    const std::vector<int> index = face_indices_with_edge_angles(m_mesh, m_connection, m_adjustment->edges(), rho, u);
    check_prescribed_indices(index, k, request.loop_turns.empty());
    report_indices(index, result, answer);
    result.loop_turns = m_adjustment->turns_of_field(m_mesh, rho, u);
    write_directions(u, result.degree, targets.constraints, result, answer);
    answer.magnitudes.resize(u.size());
    for(std::size_t v = 0; v < u.size(); ++v) answer.magnitudes[v] = std::abs(u[v]);  // 1, 0 at isolated vertices
    result.timings.total_ms = milliseconds_since(start);
    result.timings.solve_ms = result.timings.total_ms - result.timings.setup_ms - result.timings.factorization_ms;
    return result;
  }

  void prepare_adjustment()
  {
    if(!m_adjustment) m_adjustment = std::make_unique<Connection_adjustment>(m_mesh, m_components);
  }

  // rho_e of the connection of the given degree (updated), per edge
  const Eigen::VectorXd& transport_angles(int degree)
  {
    if(m_transport_angles_degree != degree)
    {
      m_transport_angles = m_adjustment->transport_angles(m_connection);
      m_transport_angles_degree = degree;
    }
    return m_transport_angles;
  }

  // How the field turns along the loops of prescription_loops(): what
  // prescribed_loop_turns takes to give its singularities back.
  std::vector<std::pair<std::size_t, int> > loop_turns_of(const std::vector<Complex>& u, int degree,
                                                          const std::vector<Component_report>& components)
  {
    // loops that can be chosen: 2g through the handles and the boundary loops but one, 1 - chi on a
    // component with boundary, 2 - chi on a closed one; none on spheres and disks (no cycle basis built)
    long loops = 0;
    for(const Component_report& c : components) loops += (c.is_closed ? 2 : 1) - c.euler_characteristic;
    if(loops <= 0) return {};
    prepare_adjustment();
    return m_adjustment->turns_of_field(m_mesh, transport_angles(degree), u);
  }

  // The turns asked of the loops of prescription_loops() (0 where not asked).
  struct Loop_turns
  {
    std::vector<int> turns;
    std::vector<unsigned char> asked;
  };

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

  // The requests that have no meaning for a prescribed field (it solves no
  // eigenproblem and no aligned system).
  static void refuse_with_prescription(const Field_request& request, const Field_targets& targets)
  {
    if(targets.alignment.lambda_given || targets.alignment.weight_given)
      throw Invalid_input_error("alignment_lambda and alignment_weight do not apply to prescribed singularities "
                                "(the guidance only chooses the field's rotation)");
    if(targets.alignment.eigenvalue_bound)
      throw Invalid_input_error("compute_eigenvalue_bound does not apply to prescribed singularities");
    if(request.distributed != nullptr)
      throw Invalid_input_error("prescribed singularities are computed by one process: no distributed_solver");
  }

  // The rotation of component c's parallel field: by its first constrained
  // vertex (the others must agree), or the one that best follows the
  // guidance (the angle of sum_v area_v q_v conj(u_v)).
  void rotate_component(std::size_t c, const Field_targets& targets, std::vector<Complex>& u) const
  {
    const Component& comp = m_components.list[c];
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
        for(std::size_t corner : m_mesh.fan(v)) area += m_tangent_spaces.face_area[corner / 3];
        rotation += area * targets.guidance[v] * std::conj(u[v]);
      }
    if(!(std::abs(rotation) > 0.) || !std::isfinite(std::abs(rotation))) return;
    rotation /= std::abs(rotation);
    for(std::size_t v : comp.vertices) u[v] *= rotation;
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
  // |x_e| reached pi: then the prescription asks more of an edge than a field
  // on the vertices can show (singularities in neighbouring faces, or a
  // vertex whose angle defect times n is a full turn or more, as at the
  // corners of a cube, made singularity-free).
  // A surface with handles or several boundary loops may need the turns
  // along its loops as well: the least change with 0 turns can pass pi
  // along an edge where the field's own turns would not.
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
          "spread singularities that are close together, or refine the mesh where curvature is concentrated",
          f);
  }

  // Eigenvalues and lambda_t between the user's units and those of the
  // normalized coordinates (normalize_coordinates(): lengths times
  // m_length_scale, eigenvalues divided by its square).
  double eigenvalue_to_user(double lambda) const { return lambda * m_length_scale * m_length_scale; }
  double eigenvalue_from_user(double lambda) const { return lambda / m_length_scale / m_length_scale; }

  static double milliseconds_since(Clock::time_point start)
  {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
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

  // The constraints and the alignment request (the guidance is computed by read_guidance()).
  Field_targets field_targets(const Field_request& request) const
  {
    Field_targets targets;
    targets.constraints = vertex_constraints(m_mesh, m_tangent_spaces, request, m_normals);
    add_feature_constraints(request, m_mesh, m_tangent_spaces, m_normals, targets.constraints);
    targets.has_guidance = request.has_guidance_map || request.curvature != Principal_curvature_alignment::NONE;
    targets.alignment = request.alignment;
    return targets;
  }

  // targets.guidance, computed while the factorizations that do not depend
  // on it run (counted as factorization time); after them when the guidance
  // factors a matrix of its own (the Hopf differential's estimate): two
  // factorizations side by side would make OpenBLAS's number of threads at
  // the top of each elimination tree, and with it the last digits, depend on
  // their timing (Single_threaded_blas in dense_kernels.h).
  void read_guidance(const Field_request& request, const std::vector<std::size_t>& early,
                     SparseSolver& linear_solver, Field_targets& targets, Direction_field_timings& timings)
  {
    auto compute_guidance = [&] {
      targets.guidance = guidance_coefficients(m_mesh, m_tangent_spaces, m_components, request, m_normals,
                                                linear_solver);
    };
    auto factor_early = [&] {
      for(std::size_t c : early) factor_aligned_system(c, targets.alignment.lambda);
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
      prepare_mass_operator();
      factor_early();
    }
    else
      parallel_invoke([&] { compute_guidance(); prepare_mass_operator(); }, factor_early);
    timings.factorization_ms += milliseconds_since(start);
  }

  // The components whose aligned system A - lambda_t M is known before the
  // guidance: lambda_t given or the default 0, no constraint, nothing that
  // needs lambda_1 first, a solver that certifies definiteness. (If the
  // guidance then vanishes on a component, its field is the smoothest one and
  // this factorization is not used.)
  std::vector<std::size_t> factored_before_guidance(const Field_targets& targets, bool user_solver) const
  {
    std::vector<std::size_t> early;
    if(!targets.has_guidance || user_solver || targets.alignment.weight_given || targets.alignment.eigenvalue_bound)
      return early;
    for(std::size_t c = 0; c < m_components.list.size(); ++c)
      if(certifies_definiteness(c) && component_constraints(m_components.list[c], targets.constraints).empty())
        early.push_back(c);
    return early;
  }

  // Factors A - lambda M of component c for its aligned field (kept for
  // solve_below_smallest_eigenvalue()). In a single call (the free function)
  // the aligned field needs only two products with M besides this
  // factorization, which Mass_operator computes from the faces: the
  // assembly then gives the matrix to factor directly, without A and M (see
  // shift_only()), or A and M are freed before the factorization, the moment
  // of peak memory.
  void factor_aligned_system(std::size_t c, double lambda)
  {
    typedef Factored_matrix<SparseSolver> Factored;
    Component_factorization& kept = component_factorization(c, false);
    Complex_sparse_matrix S;
    if(c < m_shifted_lower.size() && m_shifted_lower[c].matrix.rows() != 0 && m_shifted_lower[c].shift == -lambda)
      S.swap(m_shifted_lower[c].matrix);
    else
    {
      component_scale(c);  // kept beyond the matrices
      S = Factored::matrix_to_factor(component_matrices(c).energy, component_matrices(c).mass, -lambda);
    }
    if(!m_keep_factorizations)  // swapped with empty ones: Eigen's assignment of an empty matrix keeps the memory
    {
      Complex_sparse_matrix().swap(m_matrices[c].energy);
      Complex_sparse_matrix().swap(m_matrices[c].mass);
    }
    const bool factored_ok = kept.factored.factor_if_positive_definite(S, kept.analyzed);
    kept.analyzed = true;
    kept.aligned_lambda = factored_ok ? lambda : std::numeric_limits<double>::quiet_NaN();
    kept.indefinite_lambda = factored_ok ? std::numeric_limits<double>::quiet_NaN() : lambda;
  }

  // M q for component c's guidance q normalized to ||q||_M = 1 (the right-hand
  // side of the aligned system); `present` tells whether it has any (zero otherwise).
  Complex_vector guidance_load(std::size_t c, const std::vector<Complex>& guidance, bool& present)
  {
    const Component& comp = m_components.list[c];
    const Eigen::Index nc = static_cast<Eigen::Index>(comp.vertices.size());
    Complex_vector q = Complex_vector::Zero(nc);
    present = false;
    if(guidance.empty()) return q;
    for(Eigen::Index i = 0; i < nc; ++i) q[i] = guidance[comp.vertices[static_cast<std::size_t>(i)]];
    Complex_vector Mq = mass_times(c, q);
    const double q_norm = std::sqrt((std::max)(0., q.dot(Mq).real()));  // dot conjugates its left argument
    present = q_norm > 0.;
    if(present) Mq /= q_norm;
    return Mq;
  }

  // Component c's share of the constraints (empty if it has none).
  static Constraints component_constraints(const Component& comp,
                                                     const Vertex_constraints& constraints)
  {
    Constraints local;
    if(constraints.is_constrained.empty()) return local;
    const Eigen::Index nc = static_cast<Eigen::Index>(comp.vertices.size());
    local.is_constrained.resize(comp.vertices.size());
    local.values.resize(nc);
    for(Eigen::Index i = 0; i < nc; ++i)
    {
      const std::size_t v = comp.vertices[static_cast<std::size_t>(i)];
      local.is_constrained[static_cast<std::size_t>(i)] = constraints.is_constrained[v];
      local.values[i] = constraints.values[v];
    }
    return local;
  }

  // The field of component c, into `field`; its report into result.components[c].
  void solve_component(std::size_t c, const Field_targets& targets, const Eigen_solve_options& options,
                       bool user_solver, SparseSolver& linear_solver, Direction_field_result& result,
                       Vertex_field& field)
  {
    const Component& comp = m_components.list[c];
    Component_report& report = result.components[c];
    describe_component(m_mesh, comp, report);
    bool aligned = false;
    const Complex_vector Mq = guidance_load(c, targets.guidance, aligned);
    const Constraints constraints = component_constraints(comp, targets.constraints);
    const bool constrained = !constraints.empty();

    // lambda_1: for the smoothest field, and as the bound of lambda_t when the
    // alignment weight is given (root finding), when it is asked for, or when
    // the solver cannot tell whether A - lambda_t M is positive definite
    const bool smoothest = !aligned && !constrained;
    const bool needs_eigenvalue = smoothest || targets.alignment.eigenvalue_bound ||
                                  (aligned && (targets.alignment.weight_given || !certifies_definiteness(c)));
    report.eigenvalue = std::numeric_limits<double>::quiet_NaN();
    Complex_vector u;
    if(needs_eigenvalue)
      u = smallest_eigenvector(c, options, user_solver, report, result.timings);
    if(!smoothest)
      u = aligned_field(c, Mq, aligned, constraints, targets.alignment, options, user_solver, linear_solver, report,
                        result.timings);

    // a solver that fails without saying so (a user's, or a library's out of
    // memory) must not turn into NaN directions in the outputs
    if(!u.allFinite() || u.size() != static_cast<Eigen::Index>(comp.vertices.size()))
      throw Solver_failure_error("the solver returned a field that is not finite on component " + std::to_string(c));
    report.low_magnitude_fraction = fraction_below(u, low_magnitude_threshold(options.residual_tolerance));
    double area = 0.;
    for(std::size_t f : comp.faces) area += m_tangent_spaces.face_area[f];
    for(std::size_t i = 0; i < comp.vertices.size(); ++i)
    {
      field.coefficients[comp.vertices[i]] = u[static_cast<Eigen::Index>(i)];
      field.magnitudes[comp.vertices[i]] = std::abs(u[static_cast<Eigen::Index>(i)]) * std::sqrt(area);
    }
  }

  // The smallest eigenpair of component c's pencil (A, M) (manual, "The Smoothest Field").
  Complex_vector smallest_eigenvector(std::size_t c, Eigen_solve_options options, bool user_solver,
                                                Component_report& report, Direction_field_timings& timings)
  {
    if(distributes(c))
      return distributed_smallest_eigenvector(c, options, report);
    Component_factorization& kept = component_factorization(c, user_solver);
    options.same_pattern = kept.analyzed && !user_solver;
    kept.analyzed = true;
    kept.aligned_lambda = std::numeric_limits<double>::quiet_NaN();
    Eigen_solve_result eig =
      smallest_eigenpair(component_matrices(c).energy, component_matrices(c).mass, kept.factored, options);
    release_factorization(c, user_solver);
    report.eigenvalue = eig.eigenvalue;
    report.iterations = eig.iterations;
    report.residual = eig.residual;
    report.converged = eig.converged;
    timings.factorization_ms += eig.factorization_ms;
    return std::move(eig.vector);
  }

  // The aligned and/or constrained field of component c: (A - lambda_t M) u = M q
  // with u fixed on the constrained vertices (manual, "Aligned and Constrained
  // Fields"), normalized to ||u||_M = 1.
  Complex_vector aligned_field(std::size_t c, const Complex_vector& Mq, bool aligned,
                                         const Constraints& constraints,
                                         const Alignment_request& request,
                                         const Eigen_solve_options& options, bool user_solver,
                                         SparseSolver& linear_solver, Component_report& report,
                                         Direction_field_timings& timings)
  {
    Complex_vector u;
    double lambda = request.lambda;
    double u_mass = std::numeric_limits<double>::quiet_NaN();  // u^* M u, if computed on the way
    if(std::isnan(report.eigenvalue)) report.converged = true;  // a direct solve (unless an eigen-solve follows)
    if(aligned && request.weight_given)
    {
      std::size_t evaluations = 0;
      Factored_matrix<SparseSolver> factored(linear_solver);
      lambda = find_lambda_for_weight(component_matrices(c).energy, component_matrices(c).mass, Mq,
                                                constraints, report.eigenvalue, request.weight, component_scale(c),
                                                factored, u, evaluations);
      report.iterations += evaluations;
    }
    else if(aligned && !request.lambda_given)
      u = solve_with_default_lambda(c, Mq, constraints, options, user_solver, linear_solver, report, timings, lambda,
                                    u_mass);
    else
    {
      // a lambda_t given (or 0 for a field with constraints only): admissible
      // when the matrix of the free vertices is positive definite (a solver
      // that cannot tell is checked against lambda_1 instead)
      const bool below_bound = certifies_definiteness(c) || !aligned || lambda < report.eigenvalue;
      if(!below_bound ||
         !solve_below_smallest_eigenvalue(c, lambda, Mq, constraints, user_solver, linear_solver, timings, u))
        refuse_lambda(c, lambda, options, user_solver, report, timings);
    }
    report.lambda = lambda;
    if(std::isnan(u_mass)) u_mass = u.dot(mass_times(c, u)).real();
    const double u_norm = std::sqrt((std::max)(0., u_mass));
    report.alignment_weight = aligned ? 1. / (1. + u_norm) : 0.;  // as alignment_weight_of()
    if(u_norm > 0.) u /= u_norm;
    return u;
  }

  // After a failed solve with lambda_t: lambda_t is not below lambda_1,
  // unless the solver cannot tell a matrix that is not positive definite
  // and lambda_t is below lambda_1 (an iterative solve that stopped
  // unconverged: the solver's failure, not the input's).
  [[noreturn]] void refuse_lambda(std::size_t c, double lambda, const Eigen_solve_options& options,
                                  bool user_solver, Component_report& report, Direction_field_timings& timings)
  {
    if(std::isnan(report.eigenvalue)) smallest_eigenvector(c, options, user_solver, report, timings);
    const std::string lambda_1 = compact_number(eigenvalue_to_user(report.eigenvalue));
    if(!certifies_definiteness(c) && lambda < report.eigenvalue)
      throw Solver_failure_error("the linear solve of component " + std::to_string(c) +
                                 " did not converge (A - lambda_t M is positive definite: lambda_1 = " + lambda_1 +
                                 ")");
    throw Invalid_input_error("alignment_lambda must be below the smallest eigenvalue lambda_1 = " + lambda_1 +
                              " of component " + std::to_string(c) + " (got " +
                              compact_number(eigenvalue_to_user(lambda)) + ")");
  }

  // The aligned field with the default lambda_t: 0, as in the paper, in one
  // factorization and one solve; unless lambda_1 is (nearly) 0 (a flat or
  // developable component), where 0 is not admissible: then, as when lambda_1
  // is known, lambda_t = min(0, lambda_1 - 1e-6 s_A). Near-zero lambda_1 shows
  // as a failed factorization or as a solution whose Rayleigh quotient is
  // tiny (it is then dominated by the eigenvector of lambda_1).
  Complex_vector solve_with_default_lambda(std::size_t c, const Complex_vector& Mq,
                                                     const Constraints& constraints,
                                                     const Eigen_solve_options& options, bool user_solver,
                                                     SparseSolver& linear_solver, Component_report& report,
                                                     Direction_field_timings& timings, double& lambda,
                                                     double& u_mass)
  {
    const double scale = component_scale(c);
    Complex_vector u;
    if(std::isnan(report.eigenvalue))
    {
      lambda = 0.;
      if(solve_below_smallest_eigenvalue(c, lambda, Mq, constraints, user_solver, linear_solver, timings, u))
      {
        // without constraints (A - lambda M) u = M q gives u^* A u = u^* M q + lambda u^* M u
        // (A itself may have been freed: see factor_aligned_system())
        u_mass = u.dot(mass_times(c, u)).real();
        const double rayleigh_quotient = constraints.empty()
                                           ? u.dot(Mq).real() / u_mass + lambda
                                           : u.dot(component_matrices(c).energy * u).real() / u_mass;
        if(rayleigh_quotient >= 1e-10 * scale) return u;
      }
      u_mass = std::numeric_limits<double>::quiet_NaN();
      smallest_eigenvector(c, options, user_solver, report, timings);
    }
    lambda = (std::min)(0., report.eigenvalue - 1e-6 * scale);
    if(!solve_below_smallest_eigenvalue(c, lambda, Mq, constraints, user_solver, linear_solver, timings, u))
      throw Solver_failure_error("the sparse solver could not factor A - lambda_t M of component " + std::to_string(c));
    return u;
  }

  // u with (A - lambda M) u = Mq on the free vertices of component c, u = c on
  // the constrained ones; false if that matrix is not positive definite (as
  // far as the solver tells). Without constraints the component's kept
  // factorization is used, and not redone for the lambda it already holds.
  bool solve_below_smallest_eigenvalue(std::size_t c, double lambda, const Complex_vector& Mq,
                                       const Constraints& constraints, bool user_solver,
                                       SparseSolver& linear_solver, Direction_field_timings& timings,
                                       Complex_vector& u)
  {
    if(distributes(c))
      return distributed_shifted_solve(c, lambda, Mq, constraints, u);
    const auto start = Clock::now();
    if(!constraints.empty())
    {
      // the matrix of the free vertices has a pattern of its own: a solver of its own
      const Shifted_system system(component_matrices(c).energy, component_matrices(c).mass, lambda,
                                            constraints);
      Factored_matrix<SparseSolver> factored(linear_solver);
      const bool factored_ok = system.factor(factored, false, detects_indefinite);
      timings.factorization_ms += milliseconds_since(start);
      if(factored_ok) u = system.solve(factored, Mq);
      return factored_ok;
    }
    Component_factorization& kept = component_factorization(c, user_solver);
    if(kept.indefinite_lambda == lambda) return false;  // factored and refused already
    if(!(kept.aligned_lambda == lambda))
    {
      const Shifted_system system(component_matrices(c).energy, component_matrices(c).mass, lambda,
                                            constraints);
      const bool factored_ok = system.factor(kept.factored, kept.analyzed && !user_solver, detects_indefinite);
      kept.analyzed = true;
      kept.aligned_lambda = factored_ok ? lambda : std::numeric_limits<double>::quiet_NaN();
      kept.indefinite_lambda = factored_ok ? std::numeric_limits<double>::quiet_NaN() : lambda;
      timings.factorization_ms += milliseconds_since(start);
      if(!factored_ok) return false;
    }
    u = kept.factored.solve(Mq);  // without constraints the system is A - lambda M itself
    release_factorization(c, user_solver);
    return true;
  }

  // The faces of non-zero index and the index sums (manual, "Singularities").
  void report_indices(const std::vector<int>& index, Direction_field_result& result, Field_answer& answer) const
  {
    for(std::size_t f = 0; f < m_mesh.number_of_faces(); ++f)
    {
      Component_report& report = result.components[m_components.component_of_face[f]];
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
    std::vector<Vec3>& directions = answer.directions;
    directions.resize(m_mesh.number_of_vertices());
    parallel_for_each_index(directions.size(), [&](std::size_t i) {
      directions[i] = tangent_direction(m_mesh, m_tangent_spaces, i, u[i], degree, m_normals[i]);
      // a prescribed direction exactly (see Vertex_constraints::shown)
      if(!constraints.shown.empty() && constraints.is_constrained[i] && norm(constraints.shown[i]) > 0.)
        directions[i] = constraints.shown[i];
    });
    for(std::size_t i = 0; i < directions.size(); ++i)
      if(m_mesh.fan_size(i) == 0) ++result.number_of_isolated_vertices;
  }

  // The shift per component (NaN: none) for which the assembly gives only
  // the lower triangle of A + shift M, without A and M: the components whose
  // aligned system is factored before the guidance (`early`), in a single
  // call (the free function), with a solver that reads that triangle only.
  std::vector<double> shift_only(const std::vector<std::size_t>& early, double lambda) const
  {
    std::vector<double> shifts;
    if(m_keep_factorizations || !Factored_matrix<SparseSolver>::factors_lower_triangle || early.empty())
      return shifts;
    shifts.assign(m_components.list.size(), std::numeric_limits<double>::quiet_NaN());
    for(std::size_t c : early) shifts[c] = -lambda;
    return shifts;
  }

  // The connection of degree n (the matrices, if any, are then outdated).
  void update_connection(int degree)
  {
    if(m_connection.transport.empty() || m_connection.degree != degree)
    {
      m_connection = compute_connection(m_mesh, m_tangent_spaces, degree);
      m_has_matrices = false;
    }
  }

  void update_matrices(int degree, double s, const std::vector<double>& shifts = {})
  {
    update_connection(degree);
    if(!(m_has_matrices && s == m_s))
    {
      m_matrices.clear();  // free the old matrices before building the new ones
      m_eigenvalue_scales.assign(m_components.list.size(), std::numeric_limits<double>::quiet_NaN());
      m_mass_operator.reset();  // its kernels depend on the degree
      m_shifted_lower.clear();
      if(m_distributed)  // the first process assembles only what it solves or what the aligned field reads
        m_matrices.resize(m_components.list.size());
      else
        m_matrices = assemble_energy_and_mass(m_mesh, m_tangent_spaces, m_connection, m_components, s,
                                                        shifts, &m_shifted_lower);
      for(std::size_t c = 0; c < m_shifted_lower.size(); ++c)
        if(m_shifted_lower[c].matrix.rows() != 0) m_eigenvalue_scales[c] = m_shifted_lower[c].eigenvalue_scale;
      for(auto& kept : m_factorizations)  // they factor the old matrices
        if(kept) kept->aligned_lambda = kept->indefinite_lambda = std::numeric_limits<double>::quiet_NaN();
      m_has_matrices = true;
      m_degree = degree;
      m_s = s;
    }
  }

  // A and M of component c, assembled when first needed (see update_matrices()):
  // also when factor_aligned_system() freed them, or the assembly gave only
  // the matrix it factors (see shift_only()).
  const Energy_and_mass& component_matrices(std::size_t c)
  {
    Energy_and_mass& em = m_matrices[c];
    if(em.energy.rows() == 0 || em.mass.rows() == 0)
      em = assemble_energy_and_mass(m_mesh, m_tangent_spaces, m_connection, m_components.list[c],
                                              m_components.local_index, m_s);
    return em;
  }

  // trace(A) / trace(M) of component c (eigenvalue_scale()), kept
  // while A and M are those of the current n and s, also when freed.
  double component_scale(std::size_t c)
  {
    double& scale = m_eigenvalue_scales[c];
    if(std::isnan(scale)) scale = eigenvalue_scale(component_matrices(c).energy, component_matrices(c).mass);
    return scale;
  }

  // M x for component c: with M, or from the faces once factor_aligned_system() freed it.
  Complex_vector mass_times(std::size_t c, const Complex_vector& x)
  {
    const Complex_sparse_matrix& M = m_matrices[c].mass;
    if(M.rows() != 0 || distributes(c) || m_keep_factorizations) return component_matrices(c).mass * x;
    prepare_mass_operator();
    return m_mass_operator->times(m_components.list[c], m_components.local_index, x);
  }

  // The products with M from the faces, for a call that frees the matrices.
  void prepare_mass_operator()
  {
    if(!m_keep_factorizations && !m_mass_operator)
      m_mass_operator = std::make_unique<Mass_operator>(m_mesh, m_tangent_spaces, m_connection);
  }

  // Whether component c is spread over the processes of a distributed backend.
  bool distributes(std::size_t c) const
  {
    return m_distributed != nullptr && m_distributed->distributes(m_components.list[c].vertices.size());
  }

  // Whether the solver of component c tells when A - lambda M is not
  // positive definite (the distributed solves do not factor).
  bool certifies_definiteness(std::size_t c) const { return detects_indefinite && !distributes(c); }

  Assembly_source assembly_source(std::size_t c) const
  {
    return {&m_mesh, &m_tangent_spaces, &m_connection, &m_components.list[c], &m_components.local_index};
  }

  // smallest_eigenvector() over the processes of the distributed backend.
  Complex_vector distributed_smallest_eigenvector(std::size_t c, const Eigen_solve_options& options,
                                                            Component_report& report)
  {
    Eigen_solve_result eig = m_distributed->smallest_eigenpair(assembly_source(c), m_s, options);
    if(eig.vector.size() != static_cast<Eigen::Index>(m_components.list[c].vertices.size()))
      throw Solver_failure_error("the distributed eigen-solve failed on component " + std::to_string(c));
    report.eigenvalue = eig.eigenvalue;
    report.iterations = eig.iterations;
    report.residual = eig.residual;
    report.converged = eig.converged;
    return std::move(eig.vector);
  }

  // solve_below_smallest_eigenvalue() over the processes of the distributed
  // backend: false if conjugate gradients did not converge.
  bool distributed_shifted_solve(std::size_t c, double lambda, const Complex_vector& Mq,
                                 const Constraints& constraints, Complex_vector& u)
  {
    Eigen_solve_options options;
    const Distributed_solve_report r =
      m_distributed->shifted_solve(assembly_source(c), m_s, lambda, Mq, constraints, options, u);
    return r.converged && u.size() == Mq.size();
  }

  // The factorization of component c: the user's solver (this call only), or
  // the component's own one, whose symbolic analysis is reused.
  Component_factorization& component_factorization(std::size_t c, bool user_solver)
  {
    if(user_solver) return *m_user_solver;
    if(m_factorizations.size() != m_components.list.size())
      m_factorizations.resize(m_components.list.size());
    if(!m_factorizations[c])
      m_factorizations[c] = std::make_unique<Component_factorization>();
    return *m_factorizations[c];
  }

  // Frees component c's factorization unless factorizations are kept.
  void release_factorization(std::size_t c, bool user_solver)
  {
    if(!m_keep_factorizations && !user_solver) m_factorizations[c].reset();
  }

  Indexed_mesh m_mesh;  // its coordinates times m_length_scale
  double m_length_scale = 1.;
  std::size_t m_tangent_plane_vertices = 0;  // laid out at folded triangles (folded_fans.h)
  Tangent_spaces m_tangent_spaces;
  Components m_components;
  std::vector<Vec3> m_normals;

  bool m_has_matrices = false;
  int m_degree = 0;
  double m_s = 0.;
  Connection m_connection;
  std::vector<Energy_and_mass> m_matrices;
  // lower(A + shift M) instead of A and M for some components, until factored (see shift_only())
  std::vector<Shifted_lower_triangle> m_shifted_lower;
  std::vector<double> m_eigenvalue_scales;                 // per component, NaN: not computed
  std::unique_ptr<Mass_operator> m_mass_operator;  // products with M once it is freed, during a call

  bool m_keep_factorizations = true;
  std::vector<std::unique_ptr<Component_factorization> > m_factorizations;
  std::unique_ptr<Component_factorization> m_user_solver;
  const Distributed_backend* m_distributed = nullptr;  // during a call with `distributed_solver`
  // for prescribed singularities: the cycle basis and the factored face Laplacian, made once per mesh
  std::unique_ptr<Connection_adjustment> m_adjustment;
  Eigen::VectorXd m_transport_angles;  // rho_e of the connection of degree m_transport_angles_degree, per edge
  int m_transport_angles_degree = 0;
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

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_ENGINE_IMPL_H
