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
#include <CGAL/Surface_mesh_direction_fields/internal/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
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
  // Vectors per block solve; the largest basis kept for Rayleigh-Ritz (its
  // memory is basis_size complex vectors); how many of its best Ritz vectors
  // a restart keeps. Keeping several matters where the lowest eigenvalues
  // cluster: on sphere_oded (n = 4) over 8 random starts, a basis of 12
  // keeping 4 needs 42-60 solves, one of 16 keeping 6 37-43, one of 8 keeping
  // 3 up to 758; on the other shared meshes all need the same solves.
  Eigen::Index block_size = 1;
  Eigen::Index basis_size = 12;
  Eigen::Index restart_size = 4;
  bool same_pattern = false;  // A + epsilon M has the pattern of the previous factorization
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

inline bool have_same_pattern(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M)
{
  return A.isCompressed() && M.isCompressed() && A.rows() == M.rows() && A.cols() == M.cols() &&
         A.nonZeros() == M.nonZeros() &&
         std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1, M.outerIndexPtr()) &&
         std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), M.innerIndexPtr());
}

// A + shift M, without Eigen's general sparse sum when both have the same
// pattern (as the assembled A and M do): a copy of A and one pass over the values.
inline Complex_sparse_matrix shifted_matrix(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, double shift)
{
  if(!have_same_pattern(A, M))
    return A + shift * M;
  Complex_sparse_matrix S = A;
  Complex* s = S.valuePtr();
  const Complex* m = M.valuePtr();
  parallel_for_each_index(static_cast<std::size_t>(S.nonZeros()), [&](std::size_t p) { s[p] += shift * m[p]; });
  return S;
}

// Y = H X for a Hermitian H stored with both triangles in compressed columns:
// row i of H is the conjugate of its column i, so each entry of Y is a dot
// product over one stored column -- contiguous reads, and rows can be
// computed in parallel without write conflicts (Eigen's column-major product
// scatters into rows instead).
inline void hermitian_multiply(const Complex_sparse_matrix& H, const Complex_dense_matrix& X, Complex_dense_matrix& Y)
{
  Y.resize(H.rows(), X.cols());
  const auto* outer = H.outerIndexPtr();
  const auto* inner = H.innerIndexPtr();
  const Complex* value = H.valuePtr();
  const auto* non_zeros = H.innerNonZeroPtr();  // null when compressed
  parallel_for_each_index(static_cast<std::size_t>(H.outerSize()), [&](std::size_t i) {
    const auto begin = outer[i];
    const auto end = non_zeros ? begin + non_zeros[i] : outer[i + 1];
    for(Eigen::Index j = 0; j < X.cols(); ++j)
    {
      const Complex* x = X.col(j).data();
      Complex sum(0., 0.);
      for(auto p = begin; p < end; ++p) sum += std::conj(value[p]) * x[inner[p]];
      Y(static_cast<Eigen::Index>(i), j) = sum;
    }
  });
}

inline Complex_dense_matrix hermitian_multiply(const Complex_sparse_matrix& H, const Complex_dense_matrix& X)
{
  Complex_dense_matrix Y;
  hermitian_multiply(H, X, Y);
  return Y;
}

// AX = A X and MX = M X for Hermitian A and M, in one pass over their
// columns when they have the same pattern (`same_pattern`): the indices are
// read once for both products, which matters on large meshes, where these
// products are limited by memory traffic.
inline void hermitian_multiply_pair(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, bool same_pattern,
                                    const Complex_dense_matrix& X, Complex_dense_matrix& AX, Complex_dense_matrix& MX)
{
  if(!same_pattern)
  {
    hermitian_multiply(A, X, AX);
    hermitian_multiply(M, X, MX);
    return;
  }
  AX.resize(A.rows(), X.cols());
  MX.resize(M.rows(), X.cols());
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  const Complex* a = A.valuePtr();
  const Complex* m = M.valuePtr();
  parallel_for_each_index(static_cast<std::size_t>(A.outerSize()), [&](std::size_t i) {
    const auto begin = outer[i], end = outer[i + 1];
    for(Eigen::Index j = 0; j < X.cols(); ++j)
    {
      const Complex* x = X.col(j).data();
      Complex sum_a(0., 0.), sum_m(0., 0.);
      for(auto p = begin; p < end; ++p)
      {
        const Complex xp = x[inner[p]];
        sum_a += std::conj(a[p]) * xp;
        sum_m += std::conj(m[p]) * xp;
      }
      AX(static_cast<Eigen::Index>(i), j) = sum_a;
      MX(static_cast<Eigen::Index>(i), j) = sum_m;
    }
  });
}


// Makes the columns of W orthonormal for the diagonal inner product
// <x, y> = x^* diag(d) y and orthogonal to the (already orthonormal) columns
// of V: block Gram-Schmidt against V, then Gram-Schmidt within W, each
// applied twice when needed for numerical orthogonality. No sparse product
// is needed.
// Columns that (numerically) lie in the span of the others are dropped.
template <typename Basis>
Complex_dense_matrix d_orthonormalize(const Eigen::VectorXd& d, const Basis& V, Complex_dense_matrix W)
{
  auto d_norm = [&d](const Complex_vector& w) { return std::sqrt(w.cwiseAbs2().dot(d)); };
  Eigen::VectorXd norm_before(W.cols());
  for(Eigen::Index j = 0; j < W.cols(); ++j) norm_before[j] = d_norm(W.col(j));
  // A second pass only when the first one removed most of W (the test of
  // Daniel, Gragg, Kaufman and Stewart): otherwise W is already orthogonal to
  // working accuracy, and each pass reads the whole basis twice.
  for(int pass = 0; pass < 2 && V.cols() > 0; ++pass)
  {
    const Complex_dense_matrix DW = d.asDiagonal() * W;
    W.noalias() -= V * (V.adjoint() * DW);
    bool accurate = true;
    for(Eigen::Index j = 0; j < W.cols(); ++j)
      accurate = accurate && d_norm(W.col(j)) > 0.5 * norm_before[j];
    if(accurate) break;
  }
  Eigen::Index kept = 0;
  for(Eigen::Index j = 0; j < W.cols(); ++j)
  {
    Complex_vector w = W.col(j);
    for(int pass = 0; pass < 2 && kept > 0; ++pass)
    {
      const Complex_vector Dw = d.asDiagonal() * w;
      for(Eigen::Index i = 0; i < kept; ++i) w -= W.col(i) * W.col(i).dot(Dw);
    }
    const double norm = d_norm(w);
    if(norm > 1e-10 * norm_before[j] && std::isfinite(norm))
      W.col(kept++) = w / norm;
  }
  return W.leftCols(kept);
}

// The smallest eigenpair of the pencil (A, M).
//
// Inverse iteration, X <- (A + epsilon M)^{-1} M X, on one factorization of
// A + epsilon M, applied to a block of `block_size` vectors (1 by default:
// on the shared meshes a block of b vectors saves fewer solves than the b
// times more work of a block solve), accelerated by Rayleigh-Ritz: the
// iterates are kept as a basis V (orthonormal for the lumped mass diag(M),
// which needs no sparse product and keeps V^* M V well conditioned) and the
// best vector of span(V) is the smallest eigenpair of the small pencil
// (V^* A V, V^* M V). Each step applies the solve to the current best Ritz
// vectors, so the basis holds the iterates of a Krylov-like sequence; on
// symmetric shapes, whose lowest eigenvalues cluster (a round sphere, a
// torus of revolution), this converges where plain inverse iteration would
// need thousands of steps. When V is full it is restarted with its
// `restart_size` best Ritz vectors (the next ones matter where eigenvalues
// cluster) and the previous best Ritz vectors, whose span holds the step
// direction (as in LOBPCG). Only V is stored (not A V, M V), so the memory is
// about `basis_size` + 2 `restart_size` vectors. (Keeping A V and M V instead
// saves the sparse products of the Ritz vector but costs more passes over
// memory: it was not faster at 400,000 faces.) The iteration stops when the relative residual of the
// best Ritz pair reaches the tolerance; `iterations` counts the solves
// (of a block each).
template <typename SparseSolver>
Eigen_solve_result smallest_eigenpair(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                      Factored_matrix<SparseSolver>& factored, const Eigen_solve_options& options)
{
  typedef std::chrono::steady_clock Clock;
  const Eigen::Index n = A.rows();
  Eigen_solve_result result;
  const Eigen::VectorXd lumped_mass = M.diagonal().real();
  const double sigma = A.diagonal().real().sum() / lumped_mass.sum();
  const double shift = options.relative_shift * sigma;
  const bool same_pattern = have_same_pattern(A, M);

  const auto t0 = Clock::now();
  factored.factor(shifted_matrix(A, M, shift), options.same_pattern);
  const auto t1 = Clock::now();

  const Eigen::Index block = (std::max)(Eigen::Index(1), (std::min)(options.block_size, n));
  const Eigen::Index basis_size =
    (std::max)((std::max)(Eigen::Index(3), options.restart_size + 2) * block, (std::min)(options.basis_size, n));

  // basis: the first `k` columns of V (allocated once)
  Complex_dense_matrix V(n, basis_size + 2 * block);
  Eigen::Index k = 0;
  Complex_dense_matrix H(0, 0), G(0, 0);  // V^* A V and V^* M V
  Complex_dense_matrix AQ, MQ;
  auto add_to_basis = [&](const Complex_dense_matrix& W) {
    const Complex_dense_matrix Q = d_orthonormalize(lumped_mass, V.leftCols(k), W);
    const Eigen::Index q = Q.cols();
    if(q == 0) return q;
    hermitian_multiply_pair(A, M, same_pattern, Q, AQ, MQ);
    H.conservativeResize(k + q, k + q);
    G.conservativeResize(k + q, k + q);
    H.topRightCorner(k, q) = V.leftCols(k).adjoint() * AQ;
    G.topRightCorner(k, q) = V.leftCols(k).adjoint() * MQ;
    H.bottomLeftCorner(q, k) = H.topRightCorner(k, q).adjoint();
    G.bottomLeftCorner(q, k) = G.topRightCorner(k, q).adjoint();
    const Complex_dense_matrix QAQ = Q.adjoint() * AQ, QMQ = Q.adjoint() * MQ;
    H.bottomRightCorner(q, q) = 0.5 * (QAQ + QAQ.adjoint());
    G.bottomRightCorner(q, q) = 0.5 * (QMQ + QMQ.adjoint());
    V.middleCols(k, q) = Q;
    k += q;
    return q;
  };
  auto random_block = [&](Eigen::Index cols, unsigned int seed) {
    Complex_dense_matrix X(n, cols);
    for(Eigen::Index j = 0; j < cols; ++j) X.col(j) = random_start_vector(n, seed + static_cast<unsigned int>(j));
    return X;
  };

  unsigned int next_seed = options.random_seed;
  add_to_basis(random_block(block, next_seed));
  next_seed += static_cast<unsigned int>(block);
  Complex_dense_matrix next = V.leftCols(k);  // the block the next solve is applied to
  Complex_dense_matrix previous(n, 0);        // the best Ritz vectors of the previous step
  Complex_dense_matrix kept(n, 0);            // the best Ritz vectors a restart keeps
  Complex_dense_matrix MX = hermitian_multiply(M, next), AU;
  Complex_vector u = next.col(0);
  while(result.iterations < options.max_iterations)
  {
#ifdef SMDF_DEBUG_RR
    const auto ts0 = Clock::now();
#endif
    const Complex_dense_matrix W = factored.solve(MX);
    ++result.iterations;
#ifdef SMDF_DEBUG_RR
    std::cerr << "solve " << std::chrono::duration<double, std::milli>(Clock::now() - ts0).count() << " ms\n";
#endif
#ifdef SMDF_DEBUG_RR
    const auto ta0 = Clock::now();
#endif
    if(k + W.cols() > basis_size)
    {
      // Restart with the best Ritz vectors and the previous best ones.
      k = 0;
      H.resize(0, 0);
      G.resize(0, 0);
      add_to_basis(kept);
      add_to_basis(previous);
    }
    if(add_to_basis(W) == 0)
    {
      // An invariant subspace: enrich with fresh random directions.
      if(k >= n || add_to_basis(random_block(block, next_seed)) == 0)
        break;
      next_seed += static_cast<unsigned int>(block);
    }

#ifdef SMDF_DEBUG_RR
    const auto tr0 = Clock::now();
    std::cerr << "add " << std::chrono::duration<double, std::milli>(tr0 - ta0).count() << " ms\n";
#endif
    // Rayleigh-Ritz: the best vectors of span(V), M-orthonormal.
    Eigen::GeneralizedSelfAdjointEigenSolver<Complex_dense_matrix> ritz(H, G);
    if(ritz.info() != Eigen::Success)
      break;  // V^* M V not positive definite: cannot happen for a positive definite M
    const Eigen::Index best = (std::min)(block, k);
    previous.swap(next);
    const Eigen::Index keep = (std::min)(k, (std::max)(best, options.restart_size));
    if(k + block > basis_size)  // the next step restarts: keep the best Ritz vectors
    {
      kept.noalias() = V.leftCols(k) * ritz.eigenvectors().leftCols(keep);
      next = kept.leftCols(best);
    }
    else
      next = V.leftCols(k) * ritz.eigenvectors().leftCols(best);
    u = next.col(0);
    if(block == 1)
      hermitian_multiply_pair(A, M, same_pattern, next, AU, MX);  // next = u
    else
    {
      hermitian_multiply(M, next, MX);
      hermitian_multiply(A, u, AU);
    }
    const double norm_u2 = (std::max)(0., u.dot(MX.col(0)).real());
    result.eigenvalue = u.dot(AU.col(0)).real() / norm_u2;
    result.residual = (AU.col(0) - result.eigenvalue * MX.col(0)).norm() / (sigma * MX.col(0).norm());
#ifdef SMDF_DEBUG_RR
    std::cerr << "rr " << std::chrono::duration<double, std::milli>(Clock::now() - tr0).count() << " ms\n";
#endif
    if(result.residual <= options.residual_tolerance)
    {
      result.converged = true;
      break;
    }
  }
  const auto t2 = Clock::now();
  const double norm_u = std::sqrt((std::max)(0., u.dot(MX.col(0)).real()));  // MX = M u (u is next's first column)
  result.vector = (norm_u > 0.) ? Complex_vector(u / norm_u) : u;
  result.factorization_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  result.solve_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  return result;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INVERSE_ITERATION_H
