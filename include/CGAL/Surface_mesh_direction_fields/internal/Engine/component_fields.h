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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_COMPONENT_FIELDS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_COMPONENT_FIELDS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/progress_report.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

// The field of one component in one compute(), for fields on vertices and
// on faces alike: the smallest eigenvector, or the aligned / constrained
// solve (user manual, "The Smoothest Field" and "Aligned and Constrained
// Fields", which hold on faces with the matrices of the faces).
//
// `Systems` gives each component's linear systems: Component_systems (on
// vertices) or Sequential_component_systems (on faces and point sets). It provides
//   Solver, Factorization (a Component_factorization<Solver>), detects_indefinite,
//   aligned_in_single_precision, unknowns(c), eigenvalue_to_user(lambda),
//   matrices(c), matrices_of_single_use(c) (null: keep them), mass_times(c, x),
//   scale(c), factorization(c), release_factorization(c), user_solver(),
//   certifies_definiteness(c), distributes(c), distributed_eigenpair(c, options)
//   and distributed_shifted_solve(c, lambda, Mq, constraints, u).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename Systems>
class Component_fields
{
  typedef typename Systems::Solver SparseSolver;

public:
  // `linear_solver`: the solver of the systems with constraints and of the
  // root finding for an alignment weight (a copy of the user's, or a new one)
  Component_fields(Systems& systems, const Eigen_solve_options& options, SparseSolver& linear_solver,
                   Direction_field_timings& timings)
    : m_systems(systems), m_options(options), m_linear_solver(linear_solver), m_timings(timings)
  {}

  // The field of component c for its guidance q (zero: none) and its
  // constraints (not normalized for the smoothest field, ||u||_M = 1
  // otherwise); its report into `report`, eigenvalues in the normalized units.
  Complex_vector field_of(std::size_t c, const Complex_vector& q, const Constraints& constraints,
                          const Alignment_request& alignment, Component_solve_report& report)
  {
    bool aligned = false;
    const Complex_vector Mq = guidance_load(c, q, aligned);
    const bool constrained = !constraints.empty();

    // lambda_1: for the smoothest field, and as the bound of lambda_t when the
    // alignment weight is given (root finding), when it is asked for, or when
    // the solver cannot tell whether A - lambda_t M is positive definite
    const bool smoothest = !aligned && !constrained;
    const bool needs_eigenvalue = smoothest || alignment.eigenvalue_bound ||
                                  (aligned && (alignment.weight_given || !m_systems.certifies_definiteness(c)));
    report.eigenvalue.reset();
    report.solve = smoothest ? Field_solve::EIGEN_SOLVE : Field_solve::LINEAR_SOLVE;
    Complex_vector u;
    if(needs_eigenvalue) u = smallest_eigenvector(c, report, !smoothest);
    if(!smoothest) u = aligned_field(c, Mq, aligned, constraints, alignment, report);
    return u;
  }

private:
  // M q normalized to ||q||_M = 1 (the right-hand side of the aligned
  // system); `present` tells whether q is not zero.
  Complex_vector guidance_load(std::size_t c, const Complex_vector& q, bool& present)
  {
    present = false;
    if(q.size() == 0 || q.isZero(0.)) return Complex_vector::Zero(static_cast<Eigen::Index>(m_systems.unknowns(c)));
    Complex_vector Mq = m_systems.mass_times(c, q);
    const double q_norm = std::sqrt((std::max)(0., q.dot(Mq).real()));  // dot conjugates its left argument
    present = q_norm > 0.;
    if(present) Mq /= q_norm;
    return Mq;
  }

  // The smallest eigenpair of component c's pencil (A, M), the eigenvalue
  // into `report`. The eigen-solve may free A and M once it no longer needs
  // them as assembled (Systems::matrices_of_single_use()), unless
  // `matrices_needed_after` (the aligned field that follows reads them).
  Complex_vector smallest_eigenvector(std::size_t c, Component_solve_report& report,
                                      bool matrices_needed_after = true)
  {
    Eigen_solve_result eig;
    if(m_systems.distributes(c))
      eig = m_systems.distributed_eigenpair(c, m_options);
    else
    {
      typename Systems::Factorization& kept = m_systems.factorization(c);
      Eigen_solve_options options = m_options;
      options.same_pattern = kept.analyzed && !m_systems.user_solver();
      kept.analyzed = true;
      kept.forget_aligned();
      Energy_and_mass* single_use = matrices_needed_after ? nullptr : m_systems.matrices_of_single_use(c);
      if(single_use != nullptr)
        eig = smallest_eigenpair_freeing_matrices(single_use->energy, single_use->mass, kept.factored, options);
      else
      {
        const Energy_and_mass& em = m_systems.matrices(c);
        eig = smallest_eigenpair(em.energy, em.mass, kept.factored, options);
      }
      m_systems.release_factorization(c);
      m_timings.factorization_ms += eig.factorization_ms;
    }
    report.eigenvalue = eig.eigenvalue;
    report.iterations = eig.iterations;
    report.residual = eig.residual;
    report.converged = eig.converged;
    return std::move(eig.vector);
  }

  // The aligned and/or constrained field of component c: (A - lambda_t M) u = M q
  // with u fixed on the constrained elements (manual, "Aligned and Constrained
  // Fields"), normalized to ||u||_M = 1.
  Complex_vector aligned_field(std::size_t c, const Complex_vector& Mq, bool aligned, const Constraints& constraints,
                               const Alignment_request& request, Component_solve_report& report)
  {
    Complex_vector u;
    double lambda = request.lambda;
    std::optional<double> u_mass;  // u^* M u, if computed on the way
    if(!report.eigenvalue) report.converged = true;  // a direct solve (unless an eigen-solve follows)
    if(aligned && request.weight_given)
    {
      std::size_t evaluations = 0;
      Factored_matrix<SparseSolver> factored(m_linear_solver);
      const Energy_and_mass& em = m_systems.matrices(c);
      lambda = find_lambda_for_weight(em.energy, em.mass, Mq, constraints, *report.eigenvalue, request.weight,
                                      m_systems.scale(c), factored, u, evaluations);
      report.iterations += evaluations;
    }
    else if(aligned && !request.lambda_given)
      u = solve_with_default_lambda(c, Mq, constraints, report, lambda, u_mass);
    else
    {
      // a lambda_t given (or 0 for a field with constraints only): admissible
      // when the matrix of the free elements is positive definite (a solver
      // that cannot tell is checked against lambda_1 instead)
      const bool below_bound = m_systems.certifies_definiteness(c) || !aligned || lambda < *report.eigenvalue;
      if(!below_bound || !solve_below_smallest_eigenvalue(c, lambda, Mq, constraints, u)) refuse_lambda(c, lambda, report);
    }
    report.lambda = lambda;
    if(!u_mass) u_mass = u.dot(m_systems.mass_times(c, u)).real();
    const double u_norm = std::sqrt((std::max)(0., *u_mass));
    report.alignment_weight = aligned ? 1. / (1. + u_norm) : 0.;  // as alignment_weight_of()
    if(u_norm > 0.) u /= u_norm;
    return u;
  }

  // After a failed solve with lambda_t: lambda_t is not below lambda_1,
  // unless the solver cannot tell a matrix that is not positive definite
  // and lambda_t is below lambda_1 (an iterative solve that stopped
  // unconverged: the solver's failure, not the input's).
  [[noreturn]] void refuse_lambda(std::size_t c, double lambda, Component_solve_report& report)
  {
    if(!report.eigenvalue) smallest_eigenvector(c, report);
    const std::string lambda_1 = compact_number(m_systems.eigenvalue_to_user(*report.eigenvalue));
    if(!m_systems.certifies_definiteness(c) && lambda < *report.eigenvalue)
      throw Solver_failure_error("the linear solve of component " + std::to_string(c) +
                                 " did not converge (A - lambda_t M is positive definite: lambda_1 = " + lambda_1 + ")");
    throw Invalid_input_error("alignment_lambda must be below the smallest eigenvalue lambda_1 = " + lambda_1 +
                              " of component " + std::to_string(c) + " (got " +
                              compact_number(m_systems.eigenvalue_to_user(lambda)) + ")");
  }

  // The aligned field with the default lambda_t: 0, as in the paper, in one
  // factorization and one solve; unless lambda_1 is (nearly) 0 (a flat or
  // developable component), where 0 is not admissible: then, as when lambda_1
  // is known, lambda_t = min(0, lambda_1 - 1e-6 s_A). Near-zero lambda_1 shows
  // as a failed factorization or as a solution whose Rayleigh quotient is
  // tiny (it is then dominated by the eigenvector of lambda_1).
  Complex_vector solve_with_default_lambda(std::size_t c, const Complex_vector& Mq, const Constraints& constraints,
                                           Component_solve_report& report, double& lambda,
                                           std::optional<double>& u_mass)
  {
    const double scale = m_systems.scale(c);
    Complex_vector u;
    if(!report.eigenvalue)
    {
      lambda = 0.;
      if(solve_below_smallest_eigenvalue(c, lambda, Mq, constraints, u))
      {
        // without constraints (A - lambda M) u = M q gives u^* A u = u^* M q + lambda u^* M u
        // (A itself may have been freed: see Component_systems::factor_aligned_system())
        u_mass = u.dot(m_systems.mass_times(c, u)).real();
        const double rayleigh_quotient = constraints.empty()
                                           ? u.dot(Mq).real() / *u_mass + lambda
                                           : u.dot(m_systems.matrices(c).energy * u).real() / *u_mass;
        if(rayleigh_quotient >= 1e-10 * scale) return u;
      }
      u_mass.reset();
      smallest_eigenvector(c, report);
    }
    lambda = (std::min)(0., *report.eigenvalue - 1e-6 * scale);
    if(!solve_below_smallest_eigenvalue(c, lambda, Mq, constraints, u))
      throw Solver_failure_error("the sparse solver could not factor A - lambda_t M of component " + std::to_string(c));
    return u;
  }

  // u with (A - lambda M) u = Mq on the free elements of component c, u = c on
  // the constrained ones; false if that matrix is not positive definite (as
  // far as the solver tells) or the solution is not finite. Without
  // constraints the component's kept factorization is used, and not redone
  // for the lambda it already holds.
  bool solve_below_smallest_eigenvalue(std::size_t c, double lambda, const Complex_vector& Mq,
                                       const Constraints& constraints, Complex_vector& u)
  {
    if(m_systems.distributes(c)) return m_systems.distributed_shifted_solve(c, lambda, Mq, constraints, u);
    const auto start = std::chrono::steady_clock::now();
    if(!constraints.empty())
    {
      // the matrix of the free elements has a pattern of its own: a solver of its own
      const Energy_and_mass& em = m_systems.matrices(c);
      const Shifted_system system(em.energy, em.mass, lambda, constraints);
      Factored_matrix<SparseSolver> factored(m_linear_solver);
      const bool factored_ok = system.factor(factored, false, Systems::detects_indefinite);
      m_timings.factorization_ms += milliseconds_since(start);
      if(factored_ok) u = system.solve(factored, Mq);
      return factored_ok && u.allFinite();
    }
    typename Systems::Factorization& kept = m_systems.factorization(c);
    if(kept.refused_lambda == lambda) return false;  // factored and refused already
    if(!(kept.aligned_lambda == lambda))
    {
      const Energy_and_mass& em = m_systems.matrices(c);
      const bool factored_ok =
        kept.factor_aligned(Factored_matrix<SparseSolver>::matrix_to_factor(em.energy, em.mass, -lambda),
                            kept.analyzed && !m_systems.user_solver(), Systems::detects_indefinite,
                            Systems::aligned_in_single_precision);
      kept.analyzed = true;
      if(factored_ok) kept.aligned_lambda = lambda;
      kept.refused_lambda = factored_ok ? std::nullopt : std::optional<double>(lambda);
      m_timings.factorization_ms += milliseconds_since(start);
      if(!factored_ok) return false;
    }
    // without constraints the system is A - lambda M itself
    const bool solved = kept.solve_aligned(Mq, u) && u.allFinite();
    if(!solved)
    {
      kept.forget_aligned();
      kept.refused_lambda = lambda;
    }
    m_systems.release_factorization(c);
    return solved;
  }

  Systems& m_systems;
  const Eigen_solve_options& m_options;
  SparseSolver& m_linear_solver;
  Direction_field_timings& m_timings;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_COMPONENT_FIELDS_H
