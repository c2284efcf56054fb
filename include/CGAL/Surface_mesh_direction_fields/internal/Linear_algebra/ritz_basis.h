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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_RITZ_BASIS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_RITZ_BASIS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/compact_pencil.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/hermitian_products.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/shifted_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/huge_pages.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <cstdint>
#include <random>
#include <utility>

// The space of the eigen-solve's Rayleigh-Ritz step (eigen_solve.h): the
// pencil (A, M), a basis orthonormal for the lumped mass with its projected
// pencil, and the deterministic random vectors that start or enrich it.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {
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

// Makes the columns of W orthonormal for the diagonal inner product
// <x, y> = x^* diag(d) y and orthogonal to the (already orthonormal) columns
// of V: block Gram-Schmidt against V, then Gram-Schmidt within W, each
// applied twice when needed for numerical orthogonality. No sparse product
// is needed.
// Columns that (numerically) lie in the span of the others are dropped.
template <typename Basis>
Complex_dense_matrix d_orthonormalize(const Eigen::VectorXd& d, const Basis& V, Complex_dense_matrix W)
{
  const Eigen::VectorXd norm_before = weighted_column_norms(d, W);
  Eigen::VectorXd norm = norm_before;
  // A second pass only when the first one removed most of W (the test of
  // Daniel, Gragg, Kaufman and Stewart): otherwise W is already orthogonal to
  // working accuracy, and each pass reads the whole basis twice.
  for(int pass = 0; pass < 2 && V.cols() > 0; ++pass)
  {
    combine_columns(V, weighted_adjoint_product(V, d, W), W, true);
    norm = weighted_column_norms(d, W);
    bool accurate = true;
    for(Eigen::Index j = 0; j < W.cols(); ++j) accurate = accurate && norm[j] > 0.5 * norm_before[j];
    if(accurate) break;
  }
  auto large_enough = [&](double norm_j, Eigen::Index j) { return norm_j > 1e-10 * norm_before[j] && std::isfinite(norm_j); };
  if(W.cols() == 1)
  {
    // one vector (the default block size): normalized in place, in parallel
    if(!large_enough(norm[0], 0)) return Complex_dense_matrix(W.rows(), 0);
    parallel_for_each_chunk(static_cast<std::size_t>(W.rows()), [&](std::size_t begin, std::size_t end) {
      W.col(0).segment(static_cast<Eigen::Index>(begin), static_cast<Eigen::Index>(end - begin)) /= norm[0];
    });
    return W;
  }
  auto d_norm = [&d](const auto& w) { return std::sqrt(w.cwiseAbs2().dot(d)); };
  Eigen::Index kept = 0;
  for(Eigen::Index j = 0; j < W.cols(); ++j)
  {
    Complex_vector w = W.col(j);
    for(int pass = 0; pass < 2 && kept > 0; ++pass)
    {
      const Complex_vector Dw = d.asDiagonal() * w;
      for(Eigen::Index i = 0; i < kept; ++i) w -= W.col(i) * W.col(i).dot(Dw);
    }
    const double norm_j = d_norm(w);
    if(large_enough(norm_j, j))
      W.col(kept++) = w / norm_j;
  }
  return W.leftCols(kept);
}

// The pencil (A, M) with what the iteration derives from it once: the
// assembled matrices, or their compact form (compact_pencil.h), which the
// eigen-solve of a single field moves to once nothing else reads the
// assembled ones (see use_compact_form()).
class Hermitian_pencil
{
  const Complex_sparse_matrix* m_A;
  const Complex_sparse_matrix* m_M;
  const Compact_hermitian_pencil* m_compact = nullptr;
  Eigen::Index m_rows;

public:
  Hermitian_pencil(const Complex_sparse_matrix& A_, const Complex_sparse_matrix& M_)
    : m_A(&A_), m_M(&M_), m_rows(A_.rows()), lumped_mass(M_.diagonal().real()),
      // trace(A) / trace(M) (as eigenvalue_scale(), with the lumped mass at hand)
      scale(A_.diagonal().real().sum() / lumped_mass.sum()), same_pattern(have_same_pattern(A_, M_))
  {}

  // From now on the products and the matrices to factor come from `compact`
  // (the same pencil, which must outlive this object); the assembled
  // matrices may then be freed.
  void use_compact_form(const Compact_hermitian_pencil& compact) { m_compact = &compact; }
  bool compact() const { return m_compact != nullptr; }

  Eigen::Index rows() const { return m_rows; }

  // A X and M X
  void multiply_pair(const Complex_dense_matrix& X, Complex_dense_matrix& AX, Complex_dense_matrix& MX) const
  {
    if(m_compact)
      m_compact->multiply_pair(X, AX, MX);
    else
      hermitian_multiply_pair(*m_A, *m_M, same_pattern, X, AX, MX);
  }

  // What `Factored` factors for A + shift M (only the lower triangle in the compact form, which is used only with
  // a solver that reads no more).
  template <typename Factored>
  Complex_sparse_matrix matrix_to_factor(double shift) const
  {
    if(m_compact) return m_compact->shifted_lower_triangle(shift);
    return Factored::matrix_to_factor(*m_A, *m_M, shift);
  }

  const Eigen::VectorXd lumped_mass;  // diag(M)
  const double scale;
  const bool same_pattern;  // A and M share one compressed pattern
};

// The basis V of the Rayleigh-Ritz space, orthonormal for the lumped mass
// diag(M), with the small projected pencil H = V^* A V, G = V^* M V. Its
// memory is allocated once (`capacity` columns, huge pages) and written
// column by column.
class Ritz_basis
{
  const Hermitian_pencil& m_pencil;
  Complex_dense_matrix m_V;
  Eigen::Index m_size = 0;
  Complex_dense_matrix m_H, m_G;  // V^* A V and V^* M V

public:
  Ritz_basis(const Hermitian_pencil& pencil, Eigen::Index capacity) : m_pencil(pencil), m_V(pencil.rows(), capacity)
  {
    advise_huge_pages(m_V.data(), static_cast<std::size_t>(m_V.size()) * sizeof(Complex));
  }

  Eigen::Index size() const { return m_size; }
  auto vectors() const { return m_V.leftCols(m_size); }
  const Complex_dense_matrix& projected_A() const { return m_H; }
  const Complex_dense_matrix& projected_M() const { return m_G; }

  void clear()
  {
    m_size = 0;
    m_H.resize(0, 0);
    m_G.resize(0, 0);
  }

  // Adds the part of the columns of W outside the span, orthonormalized, and
  // extends H and G; returns the number of columns added. W is taken over
  // (orthonormalized in its own storage), and A Q, M Q of the added columns
  // Q go to the caller's `AQ` and `MQ`, whose contents are lost: the
  // iteration lends its own products, which it computes again after each
  // addition, so that no vector of the size of the mesh is held twice (on
  // large meshes the iteration's vectors are a tenth of the peak memory).
  Eigen::Index add(Complex_dense_matrix W, Complex_dense_matrix& AQ, Complex_dense_matrix& MQ)
  {
    const Eigen::Index n = m_pencil.rows(), k = m_size;
    const Complex_dense_matrix Q = d_orthonormalize(m_pencil.lumped_mass, m_V.leftCols(k), std::move(W));
    const Eigen::Index q = Q.cols();
    if(q == 0) return q;
    m_pencil.multiply_pair(Q, AQ, MQ);
    // copied in parallel: most of this copy's time is the first write to the
    // basis's fresh pages
    parallel_for_each_chunk(static_cast<std::size_t>(n), [&](std::size_t begin, std::size_t end) {
      const auto first = static_cast<Eigen::Index>(begin), rows = static_cast<Eigen::Index>(end - begin);
      m_V.block(first, k, rows, q) = Q.middleRows(first, rows);
    });
    Complex_dense_matrix VAQ, VMQ;  // [V Q]^* A Q and [V Q]^* M Q, in one pass over the basis
    adjoint_products(m_V.leftCols(k + q), AQ, MQ, VAQ, VMQ);
    m_H.conservativeResize(k + q, k + q);
    m_G.conservativeResize(k + q, k + q);
    m_H.topRightCorner(k, q) = VAQ.topRows(k);
    m_G.topRightCorner(k, q) = VMQ.topRows(k);
    m_H.bottomLeftCorner(q, k) = m_H.topRightCorner(k, q).adjoint();
    m_G.bottomLeftCorner(q, k) = m_G.topRightCorner(k, q).adjoint();
    m_H.bottomRightCorner(q, q) = 0.5 * (VAQ.bottomRows(q) + VAQ.bottomRows(q).adjoint());
    m_G.bottomRightCorner(q, q) = 0.5 * (VMQ.bottomRows(q) + VMQ.bottomRows(q).adjoint());
    m_size = k + q;
    return q;
  }
};

// `cols` deterministic random vectors, seeds seed, seed + 1, ...
inline Complex_dense_matrix random_block(Eigen::Index n, Eigen::Index cols, unsigned int seed)
{
  Complex_dense_matrix X(n, cols);
  for(Eigen::Index j = 0; j < cols; ++j) X.col(j) = random_start_vector(n, seed + static_cast<unsigned int>(j));
  return X;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_RITZ_BASIS_H
