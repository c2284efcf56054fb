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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_COMPONENT_SYSTEMS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_COMPONENT_SYSTEMS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/mesh_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/distributed_backend.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/mass_operator.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

// The linear systems of each vertex field's components (user manual, "The
// Smoothest Field" and "Aligned and Constrained Fields"): what is kept of
// them between fields (Kept_systems), and the systems one compute() works
// on under its own settings (Component_systems), passed to it as arguments.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// A solver and its factorization, for one component's A + shift M: its
// symbolic analysis is reused for every later factorization (the pattern of
// A + shift M does not depend on n, s or the shift).
template <typename SparseSolver>
struct Component_factorization
{
  SparseSolver solver;
  Factored_matrix<SparseSolver> factored{solver};
  bool analyzed = false;
  // the lambda_t of the aligned system A - lambda_t M it holds, if it holds
  // one: another guidance field with the same lambda_t then costs one solve
  std::optional<double> aligned_lambda;
  std::optional<double> refused_lambda;  // the last lambda_t found too large
  // lower(A - lambda_t M) while `factored` holds it in single precision: the
  // products of the refinement (refined_solve())
  Complex_sparse_matrix refinement_matrix;

  // Factors S = lower(A - lambda_t M) for an aligned field: in single
  // precision where the solver can and `single_allowed` (each solve is then
  // refined to double precision), in double precision otherwise; false if S
  // is not positive definite (`check`; otherwise a failure throws, as factor() does).
  bool factor_aligned(Complex_sparse_matrix S, bool same_pattern, bool check = true, bool single_allowed = true)
  {
    forget_aligned();
    factored.allow_single_precision(single_allowed && Factored_matrix<SparseSolver>::factors_lower_triangle);
    bool factored_ok = true;
    if(check) factored_ok = factored.factor_if_positive_definite(S, same_pattern);
    else factored.factor(S, same_pattern);
    factored.allow_single_precision(false);
    if(factored_ok && factored.holds_single_precision()) refinement_matrix.swap(S);
    return factored_ok;
  }

  // u with S u = b for the S factor_aligned() factored; false if S turned
  // out not positive definite (the refinement did not converge and the
  // factorization in double precision failed).
  bool solve_aligned(const Complex_vector& b, Complex_vector& u)
  {
    if(factored.holds_single_precision() && refinement_matrix.rows() != 0)
    {
      if(refined_solve(factored, refinement_matrix, b, u)) return true;
      Complex_sparse_matrix S;
      S.swap(refinement_matrix);
      if(!factored.factor_if_positive_definite(S, true)) return false;
    }
    u = factored.solve(b);
    return true;
  }

  // Forgets the aligned system held (another matrix is factored next).
  void forget_aligned()
  {
    aligned_lambda.reset();
    Complex_sparse_matrix().swap(refinement_matrix);
  }
};

// The settings of one compute().
template <typename SparseSolver>
struct Call_policy
{
  const SparseSolver* user_solver = nullptr;         // for this call only, nothing kept
  const Distributed_backend* distributed = nullptr;  // the components it spreads over processes
};

// What a vertex field's engine keeps between calls: the connection of one
// degree, A and M of one (n, s) per component with their scales, and one
// factorization per component (a factorization knows which matrix it holds).
template <typename SparseSolver>
struct Kept_systems
{
  bool keep_factorizations = true;  // the setting of Globally_optimal_direction_field
  Connection connection;
  std::optional<double> matrices_s;  // the s of `matrices` (for the connection's degree); none: outdated
  std::vector<Energy_and_mass> matrices;
  std::vector<std::optional<double> > scales;  // per component
  std::vector<std::unique_ptr<Component_factorization<SparseSolver> > > factorizations;

  // The connection of degree n (the matrices, if any, are then outdated).
  const Connection& connection_of_degree(const Mesh_geometry& geometry, int degree)
  {
    if(connection.transport.empty() || connection.degree != degree)
    {
      matrices_s.reset();
      connection = compute_connection(geometry.mesh, geometry.tangent_spaces, degree);
    }
    return connection;
  }
};

// The systems of one compute(): the kept ones (Kept_systems) under the
// call's policy (Call_policy), with what the call alone uses (the user's
// solver, the products with M once the matrices are freed, the lower
// triangles assembled for early factorizations). Its end frees the
// factorizations unless they are kept; a call that fails calls
// forget_after_failure(), so that the next call starts from a consistent state.
template <typename SparseSolver>
class Component_systems
{
public:
  typedef SparseSolver Solver;
  typedef Component_factorization<SparseSolver> Factorization;
  static constexpr bool detects_indefinite = Factored_matrix<SparseSolver>::detects_indefinite;
  // Whether the aligned systems are factored in single precision where the solver can (refined solves).
  static constexpr bool aligned_in_single_precision = true;

  Component_systems(const Mesh_geometry& geometry, Kept_systems<SparseSolver>& kept,
                    const Call_policy<SparseSolver>& policy)
    : m_geometry(geometry), m_kept(kept), m_keep(kept.keep_factorizations), m_distributed(policy.distributed)
  {
    if(policy.user_solver == nullptr) return;
    m_user_factorization = std::make_unique<Factorization>();
    m_user_factorization->solver = *policy.user_solver;
  }
  ~Component_systems()
  {
    if(!m_keep) m_kept.factorizations.clear();
  }
  Component_systems(const Component_systems&) = delete;
  Component_systems& operator=(const Component_systems&) = delete;

  // Drops what a failed call may have left half made (factorizations, matrices).
  void forget_after_failure()
  {
    m_kept.factorizations.clear();
    forget_matrices();
  }

  bool keeps_factorizations() const { return m_keep; }
  bool user_solver() const { return m_user_factorization != nullptr; }
  double s() const { return m_kept.matrices_s.value_or(0.); }
  const Connection& connection() const { return m_kept.connection; }

  // A and M of every component for n and s, unless they are those already.
  // `shifts` (see shift_only()) asks for lower(A + shift M) alone where given.
  void update_matrices(int degree, double s, const std::vector<std::optional<double> >& shifts = {})
  {
    m_kept.connection_of_degree(m_geometry, degree);
    if(m_kept.matrices_s == s) return;
    forget_matrices();  // the old matrices freed before the new ones are built
    m_kept.matrices.resize(m_geometry.components.list.size());
    if(!m_distributed)  // the first process assembles only what it solves or what the aligned field reads
      m_kept.matrices = assemble_energy_and_mass(m_geometry.mesh, m_geometry.tangent_spaces, m_kept.connection,
                                                 m_geometry.components, s, shifts, &m_shifted_lower);
    for(std::size_t c = 0; c < m_shifted_lower.size(); ++c)
      if(m_shifted_lower[c].matrix.rows() != 0) m_kept.scales[c] = m_shifted_lower[c].eigenvalue_scale;
    m_kept.matrices_s = s;
  }

  // A and M of component c, assembled when first needed: also when
  // factor_aligned_system() freed them, or the assembly gave only the matrix
  // it factors (see shift_only()).
  const Energy_and_mass& matrices(std::size_t c)
  {
    Energy_and_mass& em = m_kept.matrices[c];
    if(em.energy.rows() == 0 || em.mass.rows() == 0)
      em = assemble_energy_and_mass(m_geometry.mesh, m_geometry.tangent_spaces, m_kept.connection,
                                    m_geometry.components.list[c], m_geometry.components.local_index, s());
    return em;
  }

  // trace(A) / trace(M) of component c (eigenvalue_scale()), kept while A
  // and M are those of the current n and s, also when freed.
  double scale(std::size_t c)
  {
    std::optional<double>& scale = m_kept.scales[c];
    if(!scale) scale = eigenvalue_scale(matrices(c).energy, matrices(c).mass);
    return *scale;
  }

  // M x for component c: with M, or from the faces once factor_aligned_system() freed it.
  Complex_vector mass_times(std::size_t c, const Complex_vector& x)
  {
    if(m_kept.matrices[c].mass.rows() != 0 || distributes(c) || m_keep) return matrices(c).mass * x;
    prepare_mass_operator();
    return m_mass_operator->times(m_geometry.components.list[c], m_geometry.components.local_index, x);
  }

  // The products with M from the faces, for a call that frees the matrices.
  void prepare_mass_operator()
  {
    if(!m_keep && !m_mass_operator)
      m_mass_operator = std::make_unique<Mass_operator>(m_geometry.mesh, m_geometry.tangent_spaces, m_kept.connection);
  }

  // Whether component c is spread over the processes of a distributed backend.
  bool distributes(std::size_t c) const
  {
    return m_distributed != nullptr && m_distributed->distributes(m_geometry.components.list[c].vertices.size());
  }

  // Whether the solver of component c tells when A - lambda M is not
  // positive definite (the distributed solves do not factor).
  bool certifies_definiteness(std::size_t c) const { return detects_indefinite && !distributes(c); }

  // The unknowns of component c: its vertices.
  std::size_t unknowns(std::size_t c) const { return m_geometry.components.list[c].vertices.size(); }
  double eigenvalue_to_user(double lambda) const { return m_geometry.eigenvalue_to_user(lambda); }

  // The smallest eigenpair of a component that distributes(); throws if the backend failed.
  Eigen_solve_result distributed_eigenpair(std::size_t c, const Eigen_solve_options& options) const
  {
    Eigen_solve_result eig = m_distributed->smallest_eigenpair(assembly_source(c), s(), options);
    if(eig.vector.size() != static_cast<Eigen::Index>(unknowns(c)))
      throw Solver_failure_error("the distributed eigen-solve failed on component " + std::to_string(c));
    return eig;
  }

  // (A - lambda M) u = Mq on the free vertices of a component that
  // distributes() (conjugate gradients over the processes): false if it did not converge.
  bool distributed_shifted_solve(std::size_t c, double lambda, const Complex_vector& Mq,
                                 const Constraints& constraints, Complex_vector& u) const
  {
    const Distributed_solve_report r =
      m_distributed->shifted_solve(assembly_source(c), s(), lambda, Mq, constraints, Eigen_solve_options(), u);
    return r.converged && u.size() == Mq.size();
  }

  // A and M of component c when the eigen-solve may free them (a call that
  // keeps nothing, with the package's solver), else null.
  Energy_and_mass* matrices_of_single_use(std::size_t c)
  {
    if(m_keep || user_solver()) return nullptr;
    matrices(c);
    scale(c);  // kept beyond the matrices
    return &m_kept.matrices[c];
  }

  // The shift per component (if any) for which the assembly gives only
  // the lower triangle of A + shift M, without A and M: the components whose
  // aligned system is factored before the guidance (`early`), in a call that
  // keeps no factorization, with a solver that reads that triangle only.
  std::vector<std::optional<double> > shift_only(const std::vector<std::size_t>& early, double lambda) const
  {
    std::vector<std::optional<double> > shifts;
    if(m_keep || !Factored_matrix<SparseSolver>::factors_lower_triangle || early.empty()) return shifts;
    shifts.assign(m_geometry.components.list.size(), std::nullopt);
    for(std::size_t c : early) shifts[c] = -lambda;
    return shifts;
  }

  // The factorization of component c: the user's solver (this call only), or
  // the component's own one, whose symbolic analysis is reused.
  Factorization& factorization(std::size_t c)
  {
    if(m_user_factorization)
    {
      // One solver serves every component of the call, in turn: what it
      // holds belongs to the component it served last (else the aligned
      // field of a second component with the same lambda_t would be solved
      // with the first one's factorization).
      if(m_user_factorization_component != c)
      {
        m_user_factorization->forget_aligned();
        m_user_factorization->refused_lambda.reset();
        m_user_factorization_component = c;
      }
      return *m_user_factorization;
    }
    std::vector<std::unique_ptr<Factorization> >& kept = m_kept.factorizations;
    if(kept.size() != m_geometry.components.list.size()) kept.resize(m_geometry.components.list.size());
    if(!kept[c]) kept[c] = std::make_unique<Factorization>();
    return *kept[c];
  }

  // Frees component c's factorization unless factorizations are kept.
  void release_factorization(std::size_t c)
  {
    if(!m_keep && !m_user_factorization) m_kept.factorizations[c].reset();
  }

  // Factors A - lambda M of component c for its aligned field (kept for the
  // solve that follows). In a call that keeps nothing the aligned field needs
  // only two products with M besides this factorization, which Mass_operator
  // computes from the faces: the assembly then gives the matrix to factor
  // directly, without A and M (see shift_only()), or A and M are freed before
  // the factorization, the moment of peak memory. (A single-precision factor
  // keeps that matrix, a lower triangle, for the refinement of its solves.)
  void factor_aligned_system(std::size_t c, double lambda)
  {
    Factorization& kept = factorization(c);
    Complex_sparse_matrix S;
    std::vector<Shifted_lower_triangle>& lower = m_shifted_lower;
    if(c < lower.size() && lower[c].matrix.rows() != 0 && lower[c].shift == -lambda)
      S.swap(lower[c].matrix);
    else
    {
      scale(c);  // kept beyond the matrices
      S = Factored_matrix<SparseSolver>::matrix_to_factor(matrices(c).energy, matrices(c).mass, -lambda);
    }
    if(!m_keep)  // swapped with empty ones: Eigen's assignment of an empty matrix keeps the memory
    {
      Complex_sparse_matrix().swap(m_kept.matrices[c].energy);
      Complex_sparse_matrix().swap(m_kept.matrices[c].mass);
    }
    const bool factored_ok = kept.factor_aligned(std::move(S), kept.analyzed);
    kept.analyzed = true;
    if(factored_ok) kept.aligned_lambda = lambda;
    kept.refused_lambda = factored_ok ? std::nullopt : std::optional<double>(lambda);
  }

private:
  Assembly_source assembly_source(std::size_t c) const
  {
    return {&m_geometry.mesh, &m_geometry.tangent_spaces, &m_kept.connection, &m_geometry.components.list[c],
            &m_geometry.components.local_index};
  }

  // The matrices of no n and s, and nothing factored from them.
  void forget_matrices()
  {
    m_kept.matrices_s.reset();
    m_kept.matrices.clear();
    m_kept.scales.assign(m_geometry.components.list.size(), std::nullopt);
    m_mass_operator.reset();  // its kernels depend on the degree
    m_shifted_lower.clear();
    for(auto& kept : m_kept.factorizations)  // they factor the old matrices
      if(kept)
      {
        kept->forget_aligned();
        kept->refused_lambda.reset();
      }
  }

  const Mesh_geometry& m_geometry;
  Kept_systems<SparseSolver>& m_kept;
  const bool m_keep;  // the call keeps the factorizations (and A and M)
  const Distributed_backend* const m_distributed;
  std::unique_ptr<Factorization> m_user_factorization;  // the user's solver
  std::size_t m_user_factorization_component = std::size_t(-1);  // the component it served last
  std::unique_ptr<Mass_operator> m_mass_operator;  // products with M once it is freed
  // lower(A + shift M) instead of A and M for some components, until factored (see shift_only())
  std::vector<Shifted_lower_triangle> m_shifted_lower;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_COMPONENT_SYSTEMS_H
