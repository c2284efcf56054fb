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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_LINEAR_SOLVES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_LINEAR_SOLVES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/hermitian_products.h>

#include <Eigen/Sparse>

#include <cmath>
#include <limits>
#include <vector>

// The aligned and constrained fields (user manual, section "Aligned and Constrained Fields"): the linear system
//     (A - lambda M) u = M q,     u_C = c on the constrained vertices C,
// i.e. (A - lambda M)_FF u_F = (M q)_F - (A - lambda M)_FC c on the free ones.
// For lambda < lambda_1 the matrix is Hermitian positive definite. With
// q = 0 and lambda = 0 this is the smoothest field with the values c fixed.
// The alignment weight t = 1 / (1 + ||u||_M), for ||q||_M = 1, decreases
// strictly as lambda grows from -infinity (t -> 1: the guidance itself) to
// lambda_1 (t -> 0: the smoothest field); a requested t is found by root
// finding on log(lambda_1 - lambda).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Constraints
{
  std::vector<unsigned char> is_constrained;  // per local vertex
  Complex_vector values;                       // c, used where constrained
  bool empty() const
  {
    for(unsigned char b : is_constrained) if(b) return false;
    return true;
  }
};

// The solution x of S x = b, S Hermitian given by its lower triangle
// `lower`, from `factored`, a factor of S in single precision: conjugate
// gradients preconditioned by that factor (user manual, "Performance and
// Repeated Work"). A single-precision solve is accurate to a few digits,
// and each step multiplies the error by about that accuracy, so two or
// three steps reach what a double-precision factor gives, for half its
// factorization's time and memory. The preconditioned residual z estimates
// the error; the steps stop when it is below 1e-14 of x (its recurrence,
// unlike a residual computed afresh, keeps falling below the rounding of
// S x). False, x unusable, if that takes more than `max_steps` steps or a
// step finds S not positive definite (where lambda is barely below
// lambda_1 the single factor may be too inexact): the caller then factors
// in double precision.
template <typename SparseSolver>
bool refined_solve(const Factored_matrix<SparseSolver>& factored, const Complex_sparse_matrix& lower,
                   const Complex_vector& b, Complex_vector& x, int max_steps = 20)
{
  x = factored.solve(b);
  Complex_vector r = b - lower_hermitian_times(lower, x);
  Complex_vector z = factored.solve(r);
  Complex_vector p = z;
  double rz = r.dot(z).real();
  auto converged = [&] { return !(z.norm() > 1e-14 * x.norm()); };
  for(int step = 0; step < max_steps && !converged(); ++step)
  {
    const Complex_vector Sp = lower_hermitian_times(lower, p);
    const double curvature = p.dot(Sp).real();
    if(!(curvature > 0.) || !(rz > 0.)) return false;
    const double alpha = rz / curvature;
    x += alpha * p;
    r -= alpha * Sp;
    z = factored.solve(r);
    const double rz_next = r.dot(z).real();
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return converged() && x.allFinite();
}

// The system (A - lambda M) u = b with u = c on the constrained vertices:
// factored once (a Cholesky factorization whose success certifies that the
// matrix of the free vertices is positive definite, which lambda < lambda_1
// ensures), then solved for any number of right-hand sides b.
class Shifted_system
{
  const Complex_sparse_matrix& m_A;
  const Complex_sparse_matrix& m_M;
  const double m_lambda;
  const Constraints& m_constraints;
  const bool m_constrained;
  std::vector<Eigen::Index> m_free_index;  // per vertex: its row among the free ones, -1 if constrained
  Eigen::Index m_free = 0;
  Complex_sparse_matrix m_K;  // A - lambda M, when there are constraints

public:
  Shifted_system(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, double lambda,
                 const Constraints& constraints)
    : m_A(A), m_M(M), m_lambda(lambda), m_constraints(constraints), m_constrained(!constraints.empty())
  {
    if(!m_constrained) return;
    const Eigen::Index n = A.rows();
    m_free_index.assign(static_cast<std::size_t>(n), -1);
    for(Eigen::Index i = 0; i < n; ++i)
      if(!constraints.is_constrained[static_cast<std::size_t>(i)])
        m_free_index[static_cast<std::size_t>(i)] = m_free++;
    m_K = A - lambda * M;
  }

  // Factors the matrix of the free vertices. With `check`, returns false when
  // the solver finds it is not positive definite (a solver that cannot tell,
  // see Factored_matrix::detects_indefinite, throws if it cannot factor);
  // `same_pattern`: `factored` last factored a matrix of the same pattern
  // (another lambda), so its symbolic analysis is reused.
  template <typename SparseSolver>
  bool factor(Factored_matrix<SparseSolver>& factored, bool same_pattern, bool check) const
  {
    if(!m_constrained)
    {
      if(check) return factored.factor_shifted_if_positive_definite(m_A, m_M, -m_lambda, same_pattern);
      factored.factor_shifted(m_A, m_M, -m_lambda, same_pattern);
      return true;
    }
    if(m_free == 0) return true;
    const Complex_sparse_matrix K_ff = free_block();
    if(check) return factored.factor_if_positive_definite(K_ff, same_pattern);
    factored.factor(K_ff, same_pattern);
    return true;
  }

  // u with (A - lambda M) u = b on the free vertices, u = c on the others.
  template <typename SparseSolver>
  Complex_vector solve(const Factored_matrix<SparseSolver>& factored, const Complex_vector& b) const
  {
    if(!m_constrained) return factored.solve(b);
    const Eigen::Index n = m_A.rows();
    Complex_vector u(n);
    for(Eigen::Index i = 0; i < n; ++i)
      u[i] = m_free_index[static_cast<std::size_t>(i)] < 0 ? m_constraints.values[i] : Complex(0., 0.);
    if(m_free == 0) return u;
    const Complex_vector x = factored.solve(free_right_hand_side(b, u));
    for(Eigen::Index i = 0; i < n; ++i)
      if(m_free_index[static_cast<std::size_t>(i)] >= 0) u[i] = x[m_free_index[static_cast<std::size_t>(i)]];
    return u;
  }

private:
  // K_FF, written column by column (rows stay sorted)
  Complex_sparse_matrix free_block() const
  {
    Complex_sparse_matrix K_ff(m_free, m_free);
    K_ff.reserve(m_K.nonZeros());
    for(Eigen::Index col = 0; col < m_K.outerSize(); ++col)
    {
      const Eigen::Index c = m_free_index[static_cast<std::size_t>(col)];
      if(c < 0) continue;
      K_ff.startVec(c);
      for(Complex_sparse_matrix::InnerIterator it(m_K, col); it; ++it)
      {
        const Eigen::Index r = m_free_index[static_cast<std::size_t>(it.row())];
        if(r >= 0) K_ff.insertBack(r, c) = it.value();
      }
    }
    K_ff.finalize();
    return K_ff;
  }

  // b_F - K_FC c, with c the constrained values of u
  Complex_vector free_right_hand_side(const Complex_vector& b, const Complex_vector& u) const
  {
    Complex_vector rhs(m_free);
    for(std::size_t i = 0; i < m_free_index.size(); ++i)
      if(m_free_index[i] >= 0) rhs[m_free_index[i]] = b[static_cast<Eigen::Index>(i)];
    for(Eigen::Index col = 0; col < m_K.outerSize(); ++col)
    {
      if(m_free_index[static_cast<std::size_t>(col)] >= 0) continue;
      for(Complex_sparse_matrix::InnerIterator it(m_K, col); it; ++it)
      {
        const Eigen::Index r = m_free_index[static_cast<std::size_t>(it.row())];
        if(r >= 0) rhs[r] -= it.value() * u[col];
      }
    }
    return rhs;
  }
};

// Factors and solves (A - lambda M) u = Mq with the constraints (see
// Shifted_system; throws if the matrix cannot be factored).
template <typename SparseSolver>
Complex_vector solve_shifted_system(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, double lambda,
                                    const Complex_vector& Mq, const Constraints& constraints,
                                    Factored_matrix<SparseSolver>& factored, bool same_pattern = false)
{
  const Shifted_system system(A, M, lambda, constraints);
  system.factor(factored, same_pattern, false);
  return system.solve(factored, Mq);
}

inline double alignment_weight_of(const Complex_sparse_matrix& M, const Complex_vector& u)
{
  return 1. / (1. + m_norm(M, u));
}

// lambda in (-infinity, lambda_1) with t(lambda) = target, by the Illinois
// variant of regula falsi on x = log(lambda_1 - lambda), where t is increasing
// in x. Returns lambda; `u` receives the solution there.
template <typename SparseSolver>
double find_lambda_for_weight(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, const Complex_vector& Mq,
                              const Constraints& constraints, double lambda_1, double target, double scale,
                              Factored_matrix<SparseSolver>& factored, Complex_vector& u, std::size_t& evaluations)
{
  auto weight_at = [&](double x, Complex_vector& sol) {
    sol = solve_shifted_system(A, M, lambda_1 - std::exp(x), Mq, constraints, factored, evaluations > 0);
    ++evaluations;
    return alignment_weight_of(M, sol) - target;
  };
  // bracket: start at a distance of the order of the eigenvalue scale
  double x_lo = std::log(1e-3 * scale), x_hi = x_lo;
  Complex_vector u_lo, u_hi;
  double f_lo = weight_at(x_lo, u_lo), f_hi = f_lo;
  u_hi = u_lo;
  for(int k = 0; k < 80 && f_lo > 0.; ++k) { x_hi = x_lo; f_hi = f_lo; u_hi = u_lo; x_lo -= 2.3; f_lo = weight_at(x_lo, u_lo); }
  for(int k = 0; k < 80 && f_hi < 0.; ++k) { x_lo = x_hi; f_lo = f_hi; u_lo = u_hi; x_hi += 2.3; f_hi = weight_at(x_hi, u_hi); }
  if(f_lo > 0. || f_hi < 0.)
    throw Solver_failure_error("could not reach the requested alignment weight");
  int side = 0;
  double true_lo = f_lo, true_hi = f_hi;  // f_lo, f_hi are halved by the Illinois rule
  for(int it = 0; it < 200; ++it)
  {
    if(std::abs(true_lo) <= 1e-10 || std::abs(true_hi) <= 1e-10 || x_hi - x_lo < 1e-14 * (1. + std::abs(x_lo)))
      break;
    const double x = (x_lo * f_hi - x_hi * f_lo) / (f_hi - f_lo);
    Complex_vector ux;
    const double fx = weight_at(x, ux);
    if(fx < 0.)
    {
      x_lo = x; f_lo = fx; true_lo = fx; u_lo = ux;
      if(side == -1) f_hi /= 2.;
      side = -1;
    }
    else
    {
      x_hi = x; f_hi = fx; true_hi = fx; u_hi = ux;
      if(side == 1) f_lo /= 2.;
      side = 1;
    }
  }
  const bool take_lo = std::abs(true_lo) < std::abs(true_hi);
  u = take_lo ? u_lo : u_hi;
  return lambda_1 - std::exp(take_lo ? x_lo : x_hi);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_LINEAR_SOLVES_H
