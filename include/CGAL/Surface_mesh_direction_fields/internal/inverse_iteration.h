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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSE_ITERATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSE_ITERATION_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/assembly.h>

#include <Eigen/Sparse>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>

// The smallest generalized eigenpair of A u = lambda M u (method.md, section 5),
// by inverse power iteration on one factorization of A + epsilon M, through any
// model of CGAL's `SparseLinearAlgebraWithFactorTraits_d` with complex scalars.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Eigen_solve_options
{
  // The shift epsilon is this factor times trace(A) / trace(M), a typical
  // eigenvalue of the pencil: it scales like A / M, so the shifted problem and
  // hence the result do not change when the mesh is scaled, and it is small
  // enough to leave the smallest eigenvector dominant by far, yet large enough
  // for A + epsilon M to be safely positive definite when lambda_1 = 0.
  double relative_shift = 1e-8;
  double residual_tolerance = 1e-10;
  std::size_t max_iterations = 1000;
  unsigned int random_seed = 0;
};

struct Eigen_solve_result
{
  Complex_vector vector;  // M-normalized: u^* M u = 1
  double eigenvalue = 0.;
  double residual = 0.;   // ||A u - lambda M u|| / (sigma ||M u||), sigma = trace(A)/trace(M)
  std::size_t iterations = 0;
  bool converged = false;
  double factorization_ms = 0., solve_ms = 0.;
};

// Deterministic complex start vector: the raw 64-bit Mersenne twister output is
// specified by the standard (unlike std::uniform_real_distribution), so a seed
// gives the same field on every platform.
inline Complex_vector random_start_vector(Eigen::Index n, unsigned int seed)
{
  std::mt19937_64 engine(seed);
  auto uniform = [&engine]() { return static_cast<double>(engine() >> 11) * 0x1.0p-53 * 2. - 1.; };
  Complex_vector x(n);
  for(Eigen::Index i = 0; i < n; ++i)
  {
    const double re = uniform();
    x[i] = Complex(re, uniform());
  }
  return x;
}

inline double m_norm(const Complex_sparse_matrix& M, const Complex_vector& x)
{
  return std::sqrt((std::max)(0., x.dot(M * x).real()));  // dot conjugates its left argument
}

template <typename SparseSolver>
Eigen_solve_result smallest_eigenpair(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                      SparseSolver& solver, const Eigen_solve_options& options)
{
  typedef std::chrono::steady_clock Clock;
  typedef typename SparseSolver::Matrix Solver_matrix;
  typedef typename SparseSolver::Vector Solver_vector;
  typedef typename SparseSolver::NT Solver_NT;

  const Eigen::Index n = A.rows();
  Eigen_solve_result result;
  const double sigma = A.diagonal().real().sum() / M.diagonal().real().sum();
  const double shift = options.relative_shift * sigma;

  const auto t0 = Clock::now();
  const Complex_sparse_matrix shifted = A + shift * M;
  Solver_matrix S(static_cast<int>(n), static_cast<int>(n));
  for(Eigen::Index col = 0; col < shifted.outerSize(); ++col)
    for(Complex_sparse_matrix::InnerIterator it(shifted, col); it; ++it)
      S.add_coef(static_cast<std::size_t>(it.row()), static_cast<std::size_t>(it.col()), it.value());
  Solver_NT D;
  if(!solver.factor(S, D))
    throw Solver_failure_error("the sparse solver could not factor the shifted energy matrix");
  const auto t1 = Clock::now();

  Complex_vector u = random_start_vector(n, options.random_seed);
  u /= m_norm(M, u);
  Solver_vector rhs(static_cast<int>(n)), x(static_cast<int>(n));
  for(std::size_t it = 1; it <= options.max_iterations; ++it)
  {
    const Complex_vector Mu = M * u;
    for(Eigen::Index i = 0; i < n; ++i) rhs[i] = Mu[i];
    if(!solver.linear_solver(rhs, x))
      throw Solver_failure_error("the sparse solver failed during inverse iteration");
    for(Eigen::Index i = 0; i < n; ++i) u[i] = x[i] / D;
    const double norm_u = m_norm(M, u);
    if(!(norm_u > 0.) || !std::isfinite(norm_u))
      throw Solver_failure_error("inverse iteration produced a zero or non-finite vector");
    u /= norm_u;

    const Complex_vector Au = A * u, Mu_new = M * u;
    result.eigenvalue = u.dot(Au).real();  // u^* M u = 1
    result.residual = (Au - result.eigenvalue * Mu_new).norm() / (sigma * Mu_new.norm());
    result.iterations = it;
    if(result.residual <= options.residual_tolerance)
    {
      result.converged = true;
      break;
    }
  }
  const auto t2 = Clock::now();
  result.vector = std::move(u);
  result.factorization_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  result.solve_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  return result;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSE_ITERATION_H
