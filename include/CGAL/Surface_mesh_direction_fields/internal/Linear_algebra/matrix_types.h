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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_MATRIX_TYPES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_MATRIX_TYPES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

// The types of the linear-algebra layer (internal/Linear_algebra/): complex
// coefficients, vectors and matrices. The layer works on these alone and
// includes no mesh header: a Hermitian pencil (A, M) comes in, vectors come
// out. The Hermitian matrices A and M are stored with both triangles, in
// compressed columns (Eigen's default).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

typedef std::complex<double> Complex;
typedef Eigen::SparseMatrix<Complex> Complex_sparse_matrix;
typedef Eigen::Matrix<Complex, Eigen::Dynamic, 1> Complex_vector;
typedef Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic> Complex_dense_matrix;

// The norm induced by the Hermitian positive definite M: sqrt(x^* M x).
inline double m_norm(const Complex_sparse_matrix& M, const Complex_vector& x)
{
  return std::sqrt((std::max)(0., x.dot(M * x).real()));  // dot conjugates its left argument
}

// trace(A) / trace(M): a typical eigenvalue of the pencil (A, M). It scales
// like A / M, so quantities measured against it do not change when the mesh
// is scaled (relative residuals, the default shift, the aligned solve's
// bracket).
inline double eigenvalue_scale(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M)
{
  return A.diagonal().real().sum() / M.diagonal().real().sum();
}

// The compressed pattern of a matrix analyzed ahead of its factorization
// (analyze_pattern() of the factorizations), kept until the first
// factorization checks that its matrix has exactly that pattern.
class Pending_pattern
{
  std::vector<Complex_sparse_matrix::StorageIndex> m_starts, m_rows;

public:
  void record(const Complex_sparse_matrix& S)
  {
    m_starts.assign(S.outerIndexPtr(), S.outerIndexPtr() + S.outerSize() + 1);
    m_rows.assign(S.innerIndexPtr(), S.innerIndexPtr() + S.nonZeros());
  }
  bool pending() const { return !m_starts.empty(); }
  // whether S has the recorded pattern; the record is forgotten
  bool take_and_compare(const Complex_sparse_matrix& S)
  {
    const bool matches = S.isCompressed() && static_cast<std::size_t>(S.outerSize()) + 1 == m_starts.size() &&
                         static_cast<std::size_t>(S.nonZeros()) == m_rows.size() &&
                         std::equal(m_starts.begin(), m_starts.end(), S.outerIndexPtr()) &&
                         std::equal(m_rows.begin(), m_rows.end(), S.innerIndexPtr());
    std::vector<Complex_sparse_matrix::StorageIndex>().swap(m_starts);
    std::vector<Complex_sparse_matrix::StorageIndex>().swap(m_rows);
    return matches;
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_MATRIX_TYPES_H
