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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_SHIFTED_MATRIX_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_SHIFTED_MATRIX_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <complex>
#include <cstddef>
#include <vector>

// The matrices the solver factors, A + shift M (A - sigma M for the
// eigen-solve, A - lambda M for the aligned field), built from A and M. The
// assembled A and M have the same pattern, so the sum is one pass over their
// values, without Eigen's general sparse sum; and a Cholesky solver that reads
// one triangle only gets that triangle: half the memory and half the copying
// next to the factor.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Whether A and M are compressed with the same pattern (the assembly makes
// them so): then A + shift M is one pass over both value arrays.
inline bool have_same_pattern(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M)
{
  return A.isCompressed() && M.isCompressed() && A.rows() == M.rows() && A.cols() == M.cols() &&
         A.nonZeros() == M.nonZeros() &&
         std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1, M.outerIndexPtr()) &&
         std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), M.innerIndexPtr());
}

// A + shift M, both triangles.
inline Complex_sparse_matrix shifted_matrix(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, double shift)
{
  if(!have_same_pattern(A, M))
    return A + shift * M;
  Complex_sparse_matrix S = A;
  std::complex<double>* s = S.valuePtr();
  const std::complex<double>* m = M.valuePtr();
  parallel_for_each_index(static_cast<std::size_t>(S.nonZeros()), [&](std::size_t p) { s[p] += shift * m[p]; });
  return S;
}

// The lower triangle (diagonal included) of A + shift M: in each column, the
// entries from the diagonal down, which are the end of the column since rows
// are sorted. The values are those of shifted_matrix(), bit for bit.
inline Complex_sparse_matrix shifted_lower_triangle(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                                    double shift)
{
  typedef Complex_sparse_matrix::StorageIndex Storage_index;
  if(!have_same_pattern(A, M))
    return Complex_sparse_matrix(shifted_matrix(A, M, shift).triangularView<Eigen::Lower>());
  const std::size_t n = static_cast<std::size_t>(A.cols());
  const Storage_index* outer = A.outerIndexPtr();
  const Storage_index* inner = A.innerIndexPtr();
  std::vector<Storage_index> first_lower(n);  // where column j's lower part starts
  parallel_for_each_index(n, [&](std::size_t j) {
    first_lower[j] = static_cast<Storage_index>(
      std::lower_bound(inner + outer[j], inner + outer[j + 1], static_cast<Storage_index>(j)) - inner);
  });
  Complex_sparse_matrix S(A.rows(), A.cols());
  Storage_index* s_outer = S.outerIndexPtr();
  s_outer[0] = 0;
  for(std::size_t j = 0; j < n; ++j) s_outer[j + 1] = s_outer[j] + (outer[j + 1] - first_lower[j]);
  S.resizeNonZeros(s_outer[n]);
  Storage_index* s_inner = S.innerIndexPtr();
  std::complex<double>* s_value = S.valuePtr();
  const std::complex<double>* a = A.valuePtr();
  const std::complex<double>* m = M.valuePtr();
  parallel_for_each_index(n, [&](std::size_t j) {
    Storage_index q = s_outer[j];
    for(Storage_index p = first_lower[j]; p < outer[j + 1]; ++p, ++q)
    {
      s_inner[q] = inner[p];
      s_value[q] = a[p] + shift * m[p];
    }
  });
  return S;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_SHIFTED_MATRIX_H
