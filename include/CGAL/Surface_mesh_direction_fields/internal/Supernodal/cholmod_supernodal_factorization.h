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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_CHOLMOD_SUPERNODAL_FACTORIZATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_CHOLMOD_SUPERNODAL_FACTORIZATION_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/dense_kernels.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/ordering_lock.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Supernodal/scotch_ordering.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Supernodal/supernodal_factorization.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Supernodal/supernodal_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/huge_pages.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cholmod.h>

#include <algorithm>
#include <complex>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <vector>

// A Hermitian positive definite matrix factored as P A P^T = L L^* with
// CHOLMOD's supernodal analysis, through CHOLMOD's public C interface only:
// the object owns its `cholmod_common` (its settings and workspace touch no
// other user of CHOLMOD) and its `cholmod_factor`.
//
// The numerical factorization is the package's own (supernodal_factorization.h:
// the independent subtrees of the elimination tree on the package's threads)
// when the BLAS and LAPACK kernels are linked (dense_kernels.h) and the factor
// has at least `parallel_factorization_minimum_entries` entries, CHOLMOD's
// (`cholmod_factorize`) otherwise. One right-hand side is solved by the
// package's parallel solve (supernodal_solve.h) from
// `parallel_solve_minimum_entries` entries on, blocks by `cholmod_solve`.
// Either factorization can also be stored in single precision (the package's
// own array; CHOLMOD has none), for iterations that correct their own errors.
// Every status CHOLMOD reports is checked: out of memory becomes
// std::bad_alloc, any other failure a Solver_failure_error naming the step.
// Where the address space left is too small for the BLAS's work buffers
// (dense_kernels.h, blas_work_space_available()), neither the package nor
// CHOLMOD calls the BLAS: the package factors with Eigen's kernels and
// solves every right-hand side itself.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// From this size of the matrix, the analysis asks for a nested dissection
// directly: CHOLMOD's default (AMD, then METIS as well when AMD's fill is
// high, keeping the better) ends up choosing METIS on surface meshes from
// about there on, and asking directly saves the AMD ordering. The nested
// dissection is Scotch's with CAMD (scotch_ordering.h) where the package was
// built with Scotch, in about half of METIS's time, METIS's otherwise; if
// METIS is not available either the analysis is redone with the defaults.
// The measurements are in the benchmark's README.
constexpr Eigen::Index nested_dissection_size = 600000;

// From these sizes (entries of the factor) the package's factorization and
// its solve of one right-hand side are used: below, CHOLMOD's are as fast or
// faster (benchmark's README).
constexpr std::size_t parallel_solve_minimum_entries = std::size_t(1) << 20;
constexpr std::size_t parallel_factorization_minimum_entries = std::size_t(1) << 14;

// The arrays of a supernodal factor with int indices: its structure, with
// the entries `values` (in CHOLMOD's layout, in the precision of Scalar).
template <typename Scalar>
Supernodal_factor_view<int, Scalar> supernodal_view(const cholmod_factor& L, const Scalar* values)
{
  Supernodal_factor_view<int, Scalar> view;
  view.n = L.n;
  view.supernodes = L.nsuper;
  view.super = static_cast<const int*>(L.super);
  view.row_start = static_cast<const int*>(L.pi);
  view.rows = static_cast<const int*>(L.s);
  view.value_start = static_cast<const int*>(L.px);
  view.values = values;
  view.permutation = static_cast<const int*>(L.Perm);
  return view;
}

inline bool has_sorted_rows(const Complex_sparse_matrix& S)
{
  const auto* rows = S.innerIndexPtr();
  for(Eigen::Index j = 0; j < S.outerSize(); ++j)
    if(!std::is_sorted(rows + S.outerIndexPtr()[j], rows + S.outerIndexPtr()[j + 1])) return false;
  return true;
}

// CHOLMOD's view of the lower triangle of a Hermitian matrix (no copy: the
// arrays are Eigen's; CHOLMOD's complex is interleaved (re, im), the layout
// of std::complex<double>)
inline cholmod_sparse cholmod_view_of_lower_triangle(const Complex_sparse_matrix& lower)
{
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<std::size_t>(lower.rows());
  A.nzmax = static_cast<std::size_t>(lower.nonZeros());
  A.p = const_cast<Complex_sparse_matrix::StorageIndex*>(lower.outerIndexPtr());
  A.i = const_cast<Complex_sparse_matrix::StorageIndex*>(lower.innerIndexPtr());
  A.x = const_cast<Complex*>(lower.valuePtr());
  A.stype = -1;  // only the lower triangle is read
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_COMPLEX;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = has_sorted_rows(lower);  // CHOLMOD sorts a copy otherwise
  A.packed = 1;
  return A;
}

inline cholmod_dense cholmod_view(Complex_dense_matrix& B)
{
  cholmod_dense D{};
  D.nrow = D.d = static_cast<std::size_t>(B.rows());
  D.ncol = static_cast<std::size_t>(B.cols());
  D.nzmax = D.nrow * D.ncol;
  D.x = B.data();
  D.xtype = CHOLMOD_COMPLEX;
  D.dtype = CHOLMOD_DOUBLE;
  return D;
}

class Cholmod_supernodal_factorization
{
  typedef std::complex<float> Single;

public:
  Cholmod_supernodal_factorization()
  {
    if(!cholmod_start(&m_common)) throw std::bad_alloc();
    m_common.print = 0;  // every status is checked and reported by the package
    m_common.supernodal = CHOLMOD_SUPERNODAL;
    m_common.final_asis = 1;
    m_default_first_ordering = m_common.method[0].ordering;
  }
  // (a destructor cannot report CHOLMOD's status: freeing fails only with
  // an invalid workspace, which the constructor's check excludes)
  ~Cholmod_supernodal_factorization()
  {
    if(m_factor) cholmod_free_factor(&m_factor, &m_common);
    cholmod_finish(&m_common);
  }
  Cholmod_supernodal_factorization(const Cholmod_supernodal_factorization&) = delete;
  Cholmod_supernodal_factorization& operator=(const Cholmod_supernodal_factorization&) = delete;

  // Whether the package's factorization is used where it applies (the
  // default); off, CHOLMOD factors every matrix (for comparisons).
  void use_package_factorization(bool used) { m_package_factorization_allowed = used; }

  // Whether matrices from `nested_dissection_size` rows are ordered by Scotch and
  // CAMD (scotch_ordering.h; the default where Scotch was found) or by
  // METIS (for comparisons).
  void use_scotch_ordering(bool used) { m_scotch_ordering = used && scotch_ordering_available; }

  // The symbolic analysis of a matrix with the pattern of `lower` (a lower
  // triangle). The next factorization uses it if its matrix has exactly
  // that pattern (it checks), and analyzes again otherwise.
  void analyze_pattern(const Complex_sparse_matrix& lower)
  {
    analyze(lower);
    m_pending.record(lower);
  }

  // Factors the matrix whose lower triangle is `lower` (compressed). Returns
  // false if it is not positive definite (the factor is then unusable; the
  // analysis stays valid). `same_pattern`: the caller
  // promises the pattern of the previous factorization, whose analysis is
  // then kept. `single_allowed`: the factor may be stored in single precision.
  bool factor(const Complex_sparse_matrix& lower, bool same_pattern, bool single_allowed)
  {
    const bool new_structure = prepare_analysis(lower, same_pattern);
    m_ready = m_single = m_factored_by_package = false;
    return factor_numerically(lower, new_structure, single_allowed);
  }

  Complex_dense_matrix solve(const Complex_dense_matrix& B) const
  {
    if(B.cols() == 1 && m_ready) return finite(solve_one(B));
    if(m_single || (m_ready && !m_blas_usable)) return finite(solve_columns(B));
    if(!m_factor || m_factor->minor < m_factor->n) throw Solver_failure_error("solving without a factorization");
    Complex_dense_matrix rhs = B;
    cholmod_dense b = cholmod_view(rhs);
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, m_factor, &b, &m_common);
    check_status(x != nullptr, "solving with the factor");
    Complex_dense_matrix X = Eigen::Map<const Complex_dense_matrix>(static_cast<const Complex*>(x->x), B.rows(), B.cols());
    check_status(cholmod_free_dense(&x, &m_common) != 0, "freeing a solution");
    return finite(std::move(X));
  }

  bool solves_in_parallel() const { return m_ready; }
  bool factored_by_package() const { return m_factored_by_package; }
  bool holds_single_precision() const { return m_single; }
  // CHOLMOD's factor (its values are those of the last double-precision factorization)
  const cholmod_factor* factor() const { return m_factor; }

private:
  // Throws if CHOLMOD reported an error (or `ok` is false): out of memory
  // as std::bad_alloc, anything else naming the step.
  void check_status(bool ok, const char* step) const
  {
    if(m_common.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
    if(!ok || m_common.status < CHOLMOD_OK)
      throw Solver_failure_error(std::string("CHOLMOD failed while ") + step + " (status " +
                                 std::to_string(m_common.status) + ")");
  }

  static Complex_dense_matrix finite(Complex_dense_matrix X)
  {
    if(!X.allFinite()) throw Solver_failure_error("the sparse solver failed to solve with its factorization");
    return X;
  }

  void analyze(const Complex_sparse_matrix& lower)
  {
    if(m_factor) cholmod_free_factor(&m_factor, &m_common);
    release_single_precision_factor();
    m_plan.reset();
    m_updates.reset();
    cholmod_sparse A = cholmod_view_of_lower_triangle(lower);
    const bool large = lower.rows() >= nested_dissection_size, amd_only = lower.rows() < amd_only_size;
    if(large && m_scotch_ordering && analyze_with_scotch(A)) return;
    m_common.nmethods = large || amd_only ? 1 : 0;
    m_common.method[0].ordering = large ? CHOLMOD_METIS : amd_only ? CHOLMOD_AMD : m_default_first_ordering;
    std::unique_lock<std::mutex> one_metis_ordering(metis_ordering_lock(), std::defer_lock);
    if(!amd_only) one_metis_ordering.lock();
    m_factor = cholmod_analyze(&A, &m_common);
    if(!m_factor && large && m_common.status != CHOLMOD_OUT_OF_MEMORY)
    {
      m_common.nmethods = 0;  // METIS not compiled in: CHOLMOD's defaults
      m_common.method[0].ordering = m_default_first_ordering;
      m_common.status = CHOLMOD_OK;
      m_factor = cholmod_analyze(&A, &m_common);
    }
    check_status(m_factor != nullptr, "ordering the matrix");
    m_analyzed = true;
  }

  // The analysis on Scotch's and CAMD's ordering; false (nothing analyzed)
  // if Scotch failed.
  bool analyze_with_scotch(cholmod_sparse& A)
  {
    std::vector<int> perm =
      scotch_camd_ordering(A, m_common, [this](bool ok, const char* step) { check_status(ok, step); });
    if(perm.empty()) return false;
    m_common.nmethods = 1;
    m_common.method[0].ordering = CHOLMOD_GIVEN;
    m_factor = cholmod_analyze_p(&A, perm.data(), nullptr, 0, &m_common);
    check_status(m_factor != nullptr, "analyzing the matrix on its ordering");
    m_analyzed = true;
    return true;
  }

  // Analyzes `lower` unless the kept analysis applies; returns whether the
  // structure is new.
  bool prepare_analysis(const Complex_sparse_matrix& lower, bool same_pattern)
  {
    if(m_pending.pending())
    {
      if(!m_pending.take_and_compare(lower)) analyze(lower);
      return true;
    }
    if(same_pattern && m_analyzed && m_factor) return false;
    analyze(lower);
    return true;
  }

  bool factor_numerically(const Complex_sparse_matrix& lower, bool new_structure, bool single_allowed)
  {
    m_blas_usable = blas_work_space_available();
    if(new_structure || !m_plan)
    {
      m_plan.reset();
      m_updates.reset();
    }
    if(!uses_package_factorization()) return factor_with_cholmod(lower);
    read_structure(supernodal_view(*m_factor, static_cast<const Complex*>(nullptr)));
    if(!m_plan->valid())
    {
      if(!m_blas_usable) throw std::bad_alloc();  // CHOLMOD would call the BLAS
      return factor_with_cholmod(lower);
    }
    if(!m_updates) m_updates = std::make_unique<Supernodal_updates<int> >(m_view);

    const Complex_sparse_matrix permuted = permuted_lower_triangle(lower, m_view.permutation);
    if(single_allowed && factor_in_single_precision(permuted)) return true;
    release_single_precision_factor();
    return factor_in_double_precision(permuted);
  }

  bool uses_package_factorization() const
  {
    // without the BLAS (see blas_work_space_available()), every size
    const bool large_enough = m_factor->xsize >= parallel_factorization_minimum_entries || !m_blas_usable;
    return (has_dense_kernels || !m_blas_usable) && m_package_factorization_allowed && m_factor->is_super &&
           m_factor->itype == CHOLMOD_INT && large_enough;
  }

  // the view and the solve's plan of the factor's structure (the plan is
  // kept while the analysis is)
  void read_structure(const Supernodal_factor_view<int>& view)
  {
    m_view = view;
    if(!m_plan) m_plan = std::make_unique<Supernodal_solve_plan>(m_view);
  }

  bool factor_with_cholmod(const Complex_sparse_matrix& lower)
  {
    release_single_precision_factor();
    cholmod_sparse A = cholmod_view_of_lower_triangle(lower);
    const int done = cholmod_factorize(&A, m_factor, &m_common);
    if(m_common.status == CHOLMOD_NOT_POSDEF) return false;
    check_status(done != 0, "factoring the matrix");
    if(!m_factor->is_super || m_factor->xsize < parallel_solve_minimum_entries) return true;
    read_structure(supernodal_view(*m_factor, static_cast<const Complex*>(m_factor->x)));
    m_ready = m_plan->valid();
    return true;
  }

  bool factor_in_double_precision(const Complex_sparse_matrix& permuted)
  {
    if(m_factor->xtype == CHOLMOD_PATTERN)
      check_status(cholmod_change_factor(CHOLMOD_COMPLEX, true, true, true, true, m_factor, &m_common) != 0,
                   "allocating the factor");
    m_view = supernodal_view(*m_factor, static_cast<const Complex*>(m_factor->x));
    const std::ptrdiff_t column =
      supernodal_factorize(m_view, static_cast<Complex*>(m_factor->x), permuted, *m_updates, *m_plan, m_blas_usable);
    m_factor->is_ll = true;
    m_factor->minor = column < 0 ? m_factor->n : static_cast<std::size_t>(column);
    if(column >= 0) return false;
    m_factored_by_package = true;
    m_ready = m_factor->xsize >= parallel_solve_minimum_entries || !m_blas_usable;
    return true;
  }

  // Factors in single precision into the package's own array. False if a
  // pivot is not positive in single precision, which says nothing sure
  // about the matrix: the caller then factors in double precision.
  bool factor_in_single_precision(const Complex_sparse_matrix& permuted)
  {
    if(static_cast<std::size_t>(m_single_values.size()) != m_factor->xsize)
    {
      release_single_precision_factor();
      m_single_values.resize(static_cast<Eigen::Index>(m_factor->xsize));  // not written: the advice comes first
      advise_huge_pages(m_single_values.data(), m_factor->xsize * sizeof(Single));
    }
    m_single_view = supernodal_view(*m_factor, m_single_values.data());
    const Eigen::SparseMatrix<Single> permuted_single = with_values_in_precision<Single>(permuted);
    if(supernodal_factorize(m_single_view, m_single_values.data(), permuted_single, *m_updates, *m_plan,
                            m_blas_usable) >= 0)
    {
      release_single_precision_factor();
      return false;
    }
    m_single = m_ready = m_factored_by_package = true;
    return true;
  }

  void release_single_precision_factor() { Eigen::Matrix<Single, Eigen::Dynamic, 1>().swap(m_single_values); }

  Complex_dense_matrix solve_one(const Complex_dense_matrix& B) const
  {
    if(m_single) return supernodal_solve(m_single_view, *m_plan, B.col(0));
    return supernodal_solve(m_view, *m_plan, B.col(0));
  }

  // a block column by column: CHOLMOD has no single precision, and its
  // solve calls the BLAS
  Complex_dense_matrix solve_columns(const Complex_dense_matrix& B) const
  {
    Complex_dense_matrix X(B.rows(), B.cols());
    for(Eigen::Index j = 0; j < B.cols(); ++j)
      X.col(j) = m_single ? supernodal_solve(m_single_view, *m_plan, B.col(j)) : supernodal_solve(m_view, *m_plan, B.col(j));
    return X;
  }

  mutable cholmod_common m_common;  // CHOLMOD's solve takes it non-const (workspace, status)
  cholmod_factor* m_factor = nullptr;
  bool m_analyzed = false, m_package_factorization_allowed = true;
  bool m_scotch_ordering = scotch_ordering_available;
  bool m_blas_usable = true;  // blas_work_space_available() at the last factorization
  int m_default_first_ordering = 0;
  Pending_pattern m_pending;  // the pattern analyze_pattern() analyzed, until a factorization checks it

  Supernodal_factor_view<int> m_view;
  std::unique_ptr<Supernodal_solve_plan> m_plan;  // kept while the analysis is
  std::unique_ptr<Supernodal_updates<int> > m_updates;
  bool m_ready = false;                // one right-hand side goes to the parallel solve
  bool m_factored_by_package = false;  // the last factorization was the package's
  // a factor in single precision: its entries, kept from one such
  // factorization to the next (CHOLMOD's factor then holds none)
  Eigen::Matrix<Single, Eigen::Dynamic, 1> m_single_values;
  Supernodal_factor_view<int, Single> m_single_view;
  bool m_single = false;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_CHOLMOD_SUPERNODAL_FACTORIZATION_H
