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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_COMPACT_PENCIL_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_COMPACT_PENCIL_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/shifted_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <complex>
#include <cstddef>
#include <vector>

// The pencil (A, M) of the eigen-solve in about 60% of the memory of the two
// assembled matrices: A and M are Hermitian with one pattern, so their lower
// triangles (diagonal included) hold everything, and the pattern is stored
// once. The eigen-solve of a single field (the free function) moves to this
// form once the coarse estimate and the ordering have read the assembled
// matrices (eigen_solve.h); on large meshes the matrices are, after the
// factor, the largest part of the iteration's memory (the benchmark's README).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

class Compact_hermitian_pencil
{
  typedef Complex_sparse_matrix::StorageIndex Index;

  Eigen::Index m_n = 0;
  // column j of the lower triangles: rows j (the diagonal) and up, increasing
  std::vector<Index> m_column_start, m_row;
  std::vector<Complex> m_a, m_m;
  // row i left of the diagonal: columns j < i, increasing, and where the
  // entry (i, j) is in column j's list above
  std::vector<Index> m_left_start, m_left_column, m_left_position;
  bool m_valid = true;

public:
  // From A and M that have_same_pattern() (both triangles stored, rows sorted
  // in each column, a symmetric pattern: the assembly's).
  Compact_hermitian_pencil(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M)
    : m_n(A.cols()), m_column_start(static_cast<std::size_t>(A.cols()) + 1),
      m_left_start(static_cast<std::size_t>(A.cols()) + 1)
  {
    const std::size_t n = static_cast<std::size_t>(m_n);
    const Index* outer = A.outerIndexPtr();
    const Index* inner = A.innerIndexPtr();
    std::vector<Index> diagonal(n);  // where column j's lower part starts in A
    std::vector<unsigned char> has_diagonal(n);
    parallel_for_each_index(n, [&](std::size_t j) {
      const Index* column_end = inner + outer[j + 1];
      diagonal[j] = static_cast<Index>(std::lower_bound(inner + outer[j], column_end, static_cast<Index>(j)) - inner);
      has_diagonal[j] = diagonal[j] < outer[j + 1] && inner[diagonal[j]] == static_cast<Index>(j);
    });
    m_valid = have_same_pattern(A, M) && std::find(has_diagonal.begin(), has_diagonal.end(), 0) == has_diagonal.end();
    if(!m_valid) return;
    for(std::size_t j = 0; j < n; ++j)
    {
      m_column_start[j + 1] = m_column_start[j] + (outer[j + 1] - diagonal[j]);
      // the pattern is symmetric: row j's entries left of the diagonal are column j's above it
      m_left_start[j + 1] = m_left_start[j] + (diagonal[j] - outer[j]);
    }
    copy_lower_triangles(A, M, diagonal);
    locate_left_entries(A);
  }

  // Whether A and M had the form this needs (one compressed pattern, symmetric, with the whole
  // diagonal); nothing else may be used otherwise.
  bool valid() const { return m_valid; }

  Eigen::Index rows() const { return m_n; }

  // diag(A) and diag(M) (real: A and M are Hermitian)
  Eigen::VectorXd diagonal_of_energy() const { return diagonal_of(m_a); }
  Eigen::VectorXd diagonal_of_mass() const { return diagonal_of(m_m); }

  // A X and M X. Row i sums its entries in the order of their columns, as
  // hermitian_multiply_pair() does over the assembled matrices; where those
  // are exactly Hermitian (the assembly's are: each entry off the diagonal
  // is the sum of the same two faces' terms, conjugated), the results are
  // the same bit for bit.
  void multiply_pair(const Complex_dense_matrix& X, Complex_dense_matrix& AX, Complex_dense_matrix& MX) const
  {
    AX.resize(m_n, X.cols());
    MX.resize(m_n, X.cols());
    parallel_for_each_index(static_cast<std::size_t>(m_n), [&](std::size_t i) {
      for(Eigen::Index j = 0; j < X.cols(); ++j)
      {
        const Complex* x = X.col(j).data();
        Complex sum_a(0., 0.), sum_m(0., 0.);
        for(Index q = m_left_start[i]; q < m_left_start[i + 1]; ++q)  // (i, k), k < i: stored as it is
        {
          const Complex xk = x[m_left_column[q]];
          sum_a += m_a[m_left_position[q]] * xk;
          sum_m += m_m[m_left_position[q]] * xk;
        }
        for(Index p = m_column_start[i]; p < m_column_start[i + 1]; ++p)  // (i, k), k >= i: conj of (k, i)
        {
          const Complex xk = x[m_row[p]];
          sum_a += std::conj(m_a[p]) * xk;
          sum_m += std::conj(m_m[p]) * xk;
        }
        AX(static_cast<Eigen::Index>(i), j) = sum_a;
        MX(static_cast<Eigen::Index>(i), j) = sum_m;
      }
    });
  }

  // The lower triangle of A + shift M, the values of shifted_lower_triangle() bit for bit.
  Complex_sparse_matrix shifted_lower_triangle(double shift) const
  {
    Complex_sparse_matrix S(m_n, m_n);
    std::copy(m_column_start.begin(), m_column_start.end(), S.outerIndexPtr());
    S.resizeNonZeros(static_cast<Eigen::Index>(m_row.size()));
    std::copy(m_row.begin(), m_row.end(), S.innerIndexPtr());
    Complex* s = S.valuePtr();
    parallel_for_each_index(m_row.size(), [&](std::size_t p) { s[p] = m_a[p] + shift * m_m[p]; });
    return S;
  }

private:
  Eigen::VectorXd diagonal_of(const std::vector<Complex>& values) const
  {
    Eigen::VectorXd d(m_n);
    for(std::size_t j = 0; j < static_cast<std::size_t>(m_n); ++j)
      d[static_cast<Eigen::Index>(j)] = values[static_cast<std::size_t>(m_column_start[j])].real();
    return d;
  }

  void copy_lower_triangles(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                            const std::vector<Index>& diagonal)
  {
    const std::size_t entries = static_cast<std::size_t>(m_column_start.back());
    m_row.resize(entries);
    m_a.resize(entries);
    m_m.resize(entries);
    parallel_for_each_index(static_cast<std::size_t>(m_n), [&](std::size_t j) {
      Index q = m_column_start[j];
      for(Index p = diagonal[j]; p < A.outerIndexPtr()[j + 1]; ++p, ++q)
      {
        m_row[static_cast<std::size_t>(q)] = A.innerIndexPtr()[p];
        m_a[static_cast<std::size_t>(q)] = A.valuePtr()[p];
        m_m[static_cast<std::size_t>(q)] = M.valuePtr()[p];
      }
    });
  }

  // Row i's entries left of the diagonal are at (i, k) for the rows k < i of
  // A's column i; each is found in column k's lower part by bisection.
  void locate_left_entries(const Complex_sparse_matrix& A)
  {
    const std::size_t entries = static_cast<std::size_t>(m_left_start.back());
    m_left_column.resize(entries);
    m_left_position.resize(entries);
    std::vector<unsigned char> found(static_cast<std::size_t>(m_n), 1);
    parallel_for_each_index(static_cast<std::size_t>(m_n), [&](std::size_t i) {
      Index q = m_left_start[i];
      const Index* rows = m_row.data();
      for(Index p = A.outerIndexPtr()[i]; q < m_left_start[i + 1]; ++p, ++q)
      {
        const std::size_t k = static_cast<std::size_t>(A.innerIndexPtr()[p]);
        const Index* column_end = rows + m_column_start[k + 1];
        const Index* at = std::lower_bound(rows + m_column_start[k], column_end, static_cast<Index>(i));
        found[i] = found[i] && at != column_end && *at == static_cast<Index>(i);
        m_left_column[static_cast<std::size_t>(q)] = static_cast<Index>(k);
        m_left_position[static_cast<std::size_t>(q)] = static_cast<Index>(at - rows);
      }
    });
    // every entry above the diagonal has its mirror below, and there are as
    // many below (the diagonal aside): the pattern is symmetric
    m_valid = std::find(found.begin(), found.end(), 0) == found.end() &&
              static_cast<Eigen::Index>(m_row.size()) - m_n == static_cast<Eigen::Index>(entries);
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_COMPACT_PENCIL_H
