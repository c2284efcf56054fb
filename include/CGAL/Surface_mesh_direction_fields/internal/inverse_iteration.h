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

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

// The smallest generalized eigenpair of A u = lambda M u (method.md, section 5),
// by inverse iteration on one factorization of A + epsilon M, accelerated by
// Rayleigh-Ritz on the space of its iterates, through any model of CGAL's
// `SparseLinearAlgebraWithFactorTraits_d` with complex scalars.

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

// M-orthonormalizes w against the columns of V (classical Gram-Schmidt, applied
// twice for numerical orthogonality) and returns its remaining M-norm.
inline double m_orthogonalize(const Complex_sparse_matrix& M, const std::vector<Complex_vector>& V,
                              Complex_vector& w)
{
  for(int pass = 0; pass < 2; ++pass)
  {
    const Complex_vector Mw = M * w;
    for(const Complex_vector& v : V)
      w -= v * v.dot(Mw);  // v^* M w, with v M-normalized
  }
  return m_norm(M, w);
}

// The smallest eigenpair of the pencil (A, M).
//
// The iteration is inverse power iteration, x <- (A + epsilon M)^{-1} M x, with
// one factorization of A + epsilon M; but instead of keeping only the last
// iterate it keeps the iterates as an M-orthonormal basis V (a Krylov space of
// the shifted-inverse operator, which is self-adjoint for the M inner product)
// and takes the best vector of that space by Rayleigh-Ritz: the smallest
// eigenpair of the small Hermitian matrix V^* A V. On a mesh with a clear gap
// above lambda_1 this converges like inverse iteration; on symmetric shapes,
// whose lowest eigenvalues cluster (a round sphere, a torus of revolution),
// it converges where plain inverse iteration would need thousands of steps.
// When V reaches `basis_size` vectors, it is restarted with the `kept`
// best Ritz vectors. The iteration stops when the relative residual of the
// best Ritz pair reaches the tolerance; `iterations` counts the solves.
template <typename SparseSolver>
Eigen_solve_result smallest_eigenpair(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                      SparseSolver& solver, const Eigen_solve_options& options)
{
  typedef std::chrono::steady_clock Clock;
  typedef typename SparseSolver::Matrix Solver_matrix;
  typedef typename SparseSolver::Vector Solver_vector;
  typedef typename SparseSolver::NT Solver_NT;
  typedef Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic> Dense_matrix;

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

  Solver_vector rhs(static_cast<int>(n)), x(static_cast<int>(n));
  auto apply_shifted_inverse = [&](const Complex_vector& v) {
    const Complex_vector Mv = M * v;
    for(Eigen::Index i = 0; i < n; ++i) rhs[i] = Mv[i];
    if(!solver.linear_solver(rhs, x))
      throw Solver_failure_error("the sparse solver failed during inverse iteration");
    Complex_vector y(n);
    for(Eigen::Index i = 0; i < n; ++i) y[i] = x[i] / D;
    return y;
  };

  const std::size_t basis_size = static_cast<std::size_t>((std::min)(Eigen::Index(20), n));
  const std::size_t kept = (std::min)(std::size_t(5), basis_size - 1);
  std::vector<Complex_vector> V;   // M-orthonormal basis
  std::vector<Complex_vector> AV;  // A times each basis vector
  V.reserve(basis_size);
  AV.reserve(basis_size);
  Dense_matrix H(0, 0);            // V^* A V

  auto add_to_basis = [&](Complex_vector w) {
    const double before = m_norm(M, w);
    const double after = m_orthogonalize(M, V, w);
    if(!(after > 1e-10 * before) || !std::isfinite(after))
      return false;  // w lies in span(V) (numerically)
    w /= after;
    AV.push_back(A * w);
    const Eigen::Index k = static_cast<Eigen::Index>(V.size());
    H.conservativeResize(k + 1, k + 1);
    for(Eigen::Index i = 0; i < k; ++i)
    {
      H(i, k) = V[static_cast<std::size_t>(i)].dot(AV.back());
      H(k, i) = std::conj(H(i, k));
    }
    H(k, k) = Complex(w.dot(AV.back()).real(), 0.);
    V.push_back(std::move(w));
    return true;
  };

  unsigned int extra_seed = options.random_seed;
  add_to_basis(random_start_vector(n, extra_seed));
  Complex_vector next = V.front();  // the vector the next solve is applied to
  Complex_vector u = V.front();
  while(result.iterations < options.max_iterations)
  {
    Complex_vector w = apply_shifted_inverse(next);
    ++result.iterations;
    if(!add_to_basis(w))
    {
      // Invariant subspace: enrich with a fresh random direction.
      if(V.size() >= static_cast<std::size_t>(n) || !add_to_basis(random_start_vector(n, ++extra_seed)))
        break;
    }
    next = V.back();

    // Rayleigh-Ritz: best vector of span(V).
    Eigen::SelfAdjointEigenSolver<Dense_matrix> ritz(H);
    const Complex_vector y = ritz.eigenvectors().col(0);
    u.setZero();
    Complex_vector Au = Complex_vector::Zero(n);
    for(std::size_t i = 0; i < V.size(); ++i)
    {
      u += y[static_cast<Eigen::Index>(i)] * V[i];
      Au += y[static_cast<Eigen::Index>(i)] * AV[i];
    }
    const Complex_vector Mu = M * u;
    const double norm_u = std::sqrt((std::max)(0., u.dot(Mu).real()));
    result.eigenvalue = u.dot(Au).real() / (norm_u * norm_u);
    result.residual = (Au - result.eigenvalue * Mu).norm() / (sigma * Mu.norm());
    if(result.residual <= options.residual_tolerance)
    {
      result.converged = true;
      break;
    }

    if(V.size() >= basis_size)
    {
      // Thick restart: keep the best Ritz vectors; continue the Krylov
      // sequence from the best one.
      const Eigen::Index k = static_cast<Eigen::Index>(kept);
      std::vector<Complex_vector> V_new(kept, Complex_vector::Zero(n)), AV_new(kept, Complex_vector::Zero(n));
      for(Eigen::Index j = 0; j < k; ++j)
        for(std::size_t i = 0; i < V.size(); ++i)
        {
          V_new[static_cast<std::size_t>(j)] += ritz.eigenvectors()(static_cast<Eigen::Index>(i), j) * V[i];
          AV_new[static_cast<std::size_t>(j)] += ritz.eigenvectors()(static_cast<Eigen::Index>(i), j) * AV[i];
        }
      V.swap(V_new);
      AV.swap(AV_new);
      H = Dense_matrix::Zero(k, k);
      for(Eigen::Index j = 0; j < k; ++j) H(j, j) = ritz.eigenvalues()[j];
      next = V.front();
    }
  }
  const auto t2 = Clock::now();
  const double norm_u = m_norm(M, u);
  result.vector = (norm_u > 0.) ? Complex_vector(u / norm_u) : u;
  result.factorization_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  result.solve_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  return result;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSE_ITERATION_H
