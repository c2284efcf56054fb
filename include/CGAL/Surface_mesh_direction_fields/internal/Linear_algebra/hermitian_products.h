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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_HERMITIAN_PRODUCTS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_HERMITIAN_PRODUCTS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <complex>

// The products the eigen-solve and its coarse estimate spend their memory
// traffic on: the Hermitian matrices A and M (both triangles stored, in
// compressed columns) times blocks of vectors, and the tall basis V (|V| rows,
// a dozen columns) times small matrices, or its adjoint times blocks. All run
// in parallel, over rows, with results that do not depend on the thread
// count (Eigen's own dense products run on one thread).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// y = S x for a Hermitian S given by its lower triangle in compressed
// columns (the form a factorization reads, see matrix_to_factor()): each
// stored entry below the diagonal acts twice, as S_ij and as conj(S_ij).
// One pass in column order, on one thread: it serves a few refinement steps
// (refined_solve() in linear_solves.h), where the solves dominate.
inline Complex_vector lower_hermitian_times(const Complex_sparse_matrix& lower, const Complex_vector& x)
{
  Complex_vector y = Complex_vector::Zero(lower.rows());
  for(Eigen::Index col = 0; col < lower.outerSize(); ++col)
    for(Complex_sparse_matrix::InnerIterator it(lower, col); it; ++it)
    {
      const Eigen::Index row = it.row();
      y[row] += it.value() * x[col];
      if(row != col) y[col] += std::conj(it.value()) * x[row];
    }
  return y;
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

// V^* X and V^* Y for tall V, X, Y with the same rows, in one pass over V: the
// partial products of fixed chunks of rows, added in chunk order.
inline void adjoint_products(const Eigen::Ref<const Complex_dense_matrix>& V,
                             const Eigen::Ref<const Complex_dense_matrix>& X,
                             const Eigen::Ref<const Complex_dense_matrix>& Y, Complex_dense_matrix& VX,
                             Complex_dense_matrix& VY)
{
  const Eigen::Index k = V.cols(), p = X.cols(), q = Y.cols();
  Complex_dense_matrix zero = Complex_dense_matrix::Zero(k, p + q);
  const Complex_dense_matrix both = parallel_reduce_in_order(
    static_cast<std::size_t>(V.rows()), zero,
    [&](std::size_t begin, std::size_t end) {
      const auto rows = static_cast<Eigen::Index>(end - begin), first = static_cast<Eigen::Index>(begin);
      Complex_dense_matrix part(k, p + q);
      part.leftCols(p).noalias() = V.middleRows(first, rows).adjoint() * X.middleRows(first, rows);
      part.rightCols(q).noalias() = V.middleRows(first, rows).adjoint() * Y.middleRows(first, rows);
      return part;
    },
    [](const Complex_dense_matrix& a, const Complex_dense_matrix& b) { return Complex_dense_matrix(a + b); });
  VX = both.leftCols(p);
  VY = both.rightCols(q);
}

inline Complex_dense_matrix adjoint_product(const Eigen::Ref<const Complex_dense_matrix>& V,
                                            const Eigen::Ref<const Complex_dense_matrix>& X)
{
  Complex_dense_matrix VX, unused;
  adjoint_products(V, X, X.leftCols(0), VX, unused);
  return VX;
}

// V^* diag(d) W for tall V, W with the same rows and a weight per row, by
// fixed chunks of rows (no weighted copy of W).
inline Complex_dense_matrix weighted_adjoint_product(const Eigen::Ref<const Complex_dense_matrix>& V,
                                                     const Eigen::VectorXd& d,
                                                     const Eigen::Ref<const Complex_dense_matrix>& W)
{
  const Eigen::Index k = V.cols(), p = W.cols();
  return parallel_reduce_in_order(
    static_cast<std::size_t>(V.rows()), Complex_dense_matrix(Complex_dense_matrix::Zero(k, p)),
    [&](std::size_t begin, std::size_t end) {
      const auto rows = static_cast<Eigen::Index>(end - begin), first = static_cast<Eigen::Index>(begin);
      Complex_dense_matrix part(k, p);
      part.noalias() = V.middleRows(first, rows).adjoint() * (d.segment(first, rows).asDiagonal() * W.middleRows(first, rows));
      return part;
    },
    [](const Complex_dense_matrix& a, const Complex_dense_matrix& b) { return Complex_dense_matrix(a + b); });
}

// The norms sqrt(w^* diag(d) w) of the columns w of W, by fixed chunks of rows.
inline Eigen::VectorXd weighted_column_norms(const Eigen::VectorXd& d, const Eigen::Ref<const Complex_dense_matrix>& W)
{
  const Eigen::Index p = W.cols();
  const Eigen::VectorXd squares = parallel_reduce_in_order(
    static_cast<std::size_t>(W.rows()), Eigen::VectorXd(Eigen::VectorXd::Zero(p)),
    [&](std::size_t begin, std::size_t end) {
      const auto rows = static_cast<Eigen::Index>(end - begin), first = static_cast<Eigen::Index>(begin);
      Eigen::VectorXd part(p);
      for(Eigen::Index j = 0; j < p; ++j)
        part[j] = W.col(j).segment(first, rows).cwiseAbs2().dot(d.segment(first, rows));
      return part;
    },
    [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return Eigen::VectorXd(a + b); });
  return squares.cwiseSqrt();
}

// out = V C, or out -= V C if `subtract`, for tall V and small C, by fixed
// chunks of rows.
inline void combine_columns(const Eigen::Ref<const Complex_dense_matrix>& V, const Complex_dense_matrix& C,
                            Complex_dense_matrix& out, bool subtract = false)
{
  if(!subtract) out.resize(V.rows(), C.cols());
  parallel_for_each_chunk(static_cast<std::size_t>(V.rows()), [&](std::size_t begin, std::size_t end) {
    const auto rows = static_cast<Eigen::Index>(end - begin), first = static_cast<Eigen::Index>(begin);
    if(subtract)
      out.middleRows(first, rows).noalias() -= V.middleRows(first, rows) * C;
    else
      out.middleRows(first, rows).noalias() = V.middleRows(first, rows) * C;
  });
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_HERMITIAN_PRODUCTS_H
