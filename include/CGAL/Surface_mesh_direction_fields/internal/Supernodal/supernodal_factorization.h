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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_SUPERNODAL_FACTORIZATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_SUPERNODAL_FACTORIZATION_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/dense_kernels.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/interruption.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Supernodal/supernodal_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/subnormals.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <atomic>
#include <complex>
#include <cstddef>
#include <memory>
#include <mutex>
#include <type_traits>
#include <numeric>
#include <vector>

// The numerical part of a supernodal Cholesky factorization P A P^T = L L^*
// on a symbolic analysis done elsewhere (CHOLMOD's: the layout of
// supernodal_solve.h), written into the factor's values, with the
// independent subtrees of the elimination tree on the package's threads.
//
// The algorithm is CHOLMOD's (left-looking, supernode by supernode): a
// supernode's block starts as its columns of P A P^T; each descendant whose
// rows reach the supernode's columns subtracts its product (a Hermitian
// rank-k update and a product, from the BLAS); then the diagonal block is
// factored (LAPACK) and the rows below are solved against it. A supernode
// reads only its descendants, so the subtrees of the solve's plan
// (`Supernodal_solve_plan`) are factored in parallel, each on one thread
// (dense_kernels.h says how the BLAS is kept to one thread there), and the
// top (their ancestors, where the large supernodes are) afterwards in order,
// with the BLAS's own threads. CHOLMOD
// runs all supernodes in order, so its second thread works only inside the
// few large BLAS calls; most supernodes of a surface mesh's matrix are small.
//
// Each supernode's arithmetic is the same whichever thread does it: the
// factor does not depend on the scheduling. The factor is computed in the
// precision of its entries: std::complex<double>, or std::complex<float>
// (the single-precision kernels), for a factor that half the memory holds
// and half the time reads, where inexact solves are enough
// (factored_matrix.h). In single precision the threads that run the
// package's kernels flush subnormal numbers to zero (subnormals.h): the fill
// entries that decay below float's range would otherwise take the
// processor's slow path.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The lower triangle of P S P^T, from the lower triangle of the Hermitian
// S, where row k of P S P^T is row permutation[k] of S (null: identity).
// Eigen's symmetric permutation conjugates the entries that cross the
// diagonal.
template <typename Index>
Complex_sparse_matrix permuted_lower_triangle(const Complex_sparse_matrix& lower, const Index* permutation)
{
  const Eigen::Index n = lower.rows();
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, Complex_sparse_matrix::StorageIndex> to_permuted(n);
  for(Eigen::Index k = 0; k < n; ++k)
    to_permuted.indices()[permutation ? static_cast<Eigen::Index>(permutation[k]) : k] =
      static_cast<Complex_sparse_matrix::StorageIndex>(k);
  Complex_sparse_matrix permuted(n, n);
  permuted.selfadjointView<Eigen::Lower>() = lower.selfadjointView<Eigen::Lower>().twistedBy(to_permuted);
  return permuted;
}

// The same matrix with its entries in another precision, pattern copied as
// it is. (Eigen's cast<>() rebuilds the matrix by ordered insertion, which
// asserts that the rows of each column are sorted: those of the symmetric
// permutation above are not, so it aborts in every build with assertions.)
template <typename Scalar>
Eigen::SparseMatrix<Scalar> with_values_in_precision(const Complex_sparse_matrix& S)
{
  CGAL_precondition(S.isCompressed());
  Eigen::SparseMatrix<Scalar> T(S.rows(), S.cols());
  T.resizeNonZeros(S.nonZeros());
  std::copy(S.outerIndexPtr(), S.outerIndexPtr() + S.outerSize() + 1, T.outerIndexPtr());
  std::copy(S.innerIndexPtr(), S.innerIndexPtr() + S.nonZeros(), T.innerIndexPtr());
  std::transform(S.valuePtr(), S.valuePtr() + S.nonZeros(), T.valuePtr(),
                 [](const Complex& z) { return static_cast<Scalar>(z); });
  return T;
}

// For each supernode s, the supernodes that update it: the descendants d
// with rows among s's columns, in increasing order, each with the position
// (in d's rows) of its first row in s. Computed once per symbolic structure.
template <typename Index>
class Supernodal_updates
{
public:
  template <typename Scalar>
  explicit Supernodal_updates(const Supernodal_factor_view<Index, Scalar>& L)
  {
    const std::size_t ns = L.supernodes;
    const std::vector<std::size_t> supernode_of_column = supernode_of_each_column(L);
    m_start.assign(ns + 1, 0);
    for_each_update(L, supernode_of_column, [this](std::size_t t, std::size_t, Index) { ++m_start[t + 1]; });
    std::partial_sum(m_start.begin(), m_start.end(), m_start.begin());
    m_source.resize(m_start[ns]);
    m_first_row.resize(m_start[ns]);
    std::vector<std::size_t> next(m_start.begin(), m_start.end() - 1);
    for_each_update(L, supernode_of_column, [&](std::size_t t, std::size_t d, Index p) {
      m_source[next[t]] = d;
      m_first_row[next[t]++] = p;
    });
  }

  std::size_t begin(std::size_t s) const { return m_start[s]; }
  std::size_t end(std::size_t s) const { return m_start[s + 1]; }
  std::size_t source(std::size_t k) const { return m_source[k]; }
  Index first_row(std::size_t k) const { return m_first_row[k]; }

private:
  // update(t, d, p) for each supernode d, in increasing order, and each
  // supernode t its rows below the diagonal block reach, first at position p
  template <typename Scalar, typename Update>
  static void for_each_update(const Supernodal_factor_view<Index, Scalar>& L, const std::vector<std::size_t>& supernode_of_column,
                              const Update& update)
  {
    for(std::size_t d = 0; d < L.supernodes; ++d)
    {
      const Index columns = L.super[d + 1] - L.super[d], rows = L.row_start[d + 1] - L.row_start[d];
      const Index* r = L.rows + L.row_start[d];
      std::size_t previous = L.supernodes;
      for(Index p = columns; p < rows; ++p)
      {
        const std::size_t t = supernode_of_column[static_cast<std::size_t>(r[p])];
        if(t != previous) update(t, d, p);
        previous = t;
      }
    }
  }

  std::vector<std::size_t> m_start, m_source;
  std::vector<Index> m_first_row;
};

// What one thread needs while it factors supernodes.
template <typename Index, typename Scalar>
struct Supernode_workspace
{
  std::vector<Index> position;  // row of the factor -> its row in the current block
  std::vector<Scalar> product;
  explicit Supernode_workspace(std::size_t n) : position(n) {}
};

// The block of supernode s, set to its columns of P A P^T (`lower`: the
// lower triangle of P A P^T, column-compressed).
template <typename Index, typename Scalar>
void assemble_supernode(const Supernodal_factor_view<Index, Scalar>& L, Scalar* values,
                        const Eigen::SparseMatrix<Scalar>& lower, std::size_t s, Supernode_workspace<Index, Scalar>& work)
{
  const Index first = L.super[s], columns = L.super[s + 1] - first, rows = L.row_start[s + 1] - L.row_start[s];
  Scalar* block = values + L.value_start[s];
  std::fill(block, block + static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns), Scalar(0));
  for(Index i = 0; i < rows; ++i) work.position[static_cast<std::size_t>(L.rows[L.row_start[s] + i])] = i;
  for(Index j = 0; j < columns; ++j)
  {
    Scalar* column = block + static_cast<std::size_t>(j) * static_cast<std::size_t>(rows);
    for(typename Eigen::SparseMatrix<Scalar>::InnerIterator it(lower, first + j); it; ++it)
      column[work.position[static_cast<std::size_t>(it.row())]] += it.value();
  }
}

// Subtracts from supernode s's block the products of its descendants. For
// descendant d with the rows r1 (those among s's columns) and r2 (all of
// its rows from r1 on): C = L_d[r2] L_d[r1]^*, the triangle of its top
// square by a rank-k update, the rest by a product, then scattered.
template <typename Kernels, typename Index, typename Scalar>
void apply_updates(const Supernodal_factor_view<Index, Scalar>& L, Scalar* values, const Supernodal_updates<Index>& updates,
                   std::size_t s, Supernode_workspace<Index, Scalar>& work)
{
  const Index first = L.super[s], end_column = L.super[s + 1], rows = L.row_start[s + 1] - L.row_start[s];
  Scalar* block = values + L.value_start[s];
  for(std::size_t k = updates.begin(s); k < updates.end(s); ++k)
  {
    const std::size_t d = updates.source(k);
    const Index p1 = updates.first_row(k), d_rows = L.row_start[d + 1] - L.row_start[d];
    const int d_columns = static_cast<int>(L.super[d + 1] - L.super[d]), ld = static_cast<int>(d_rows);
    const Index* r = L.rows + L.row_start[d];
    Index p2 = p1;
    while(p2 < d_rows && r[p2] < end_column) ++p2;
    const int n1 = static_cast<int>(p2 - p1), n2 = static_cast<int>(d_rows - p1), rest = n2 - n1;
    work.product.resize(static_cast<std::size_t>(n1) * static_cast<std::size_t>(n2));
    Scalar* C = work.product.data();
    const Scalar* Ld = values + L.value_start[d] + p1;
    Kernels::lower_gram(n1, d_columns, Ld, ld, C, n2);
    if(rest > 0) Kernels::product_with_adjoint(rest, n1, d_columns, Ld + n1, ld, Ld, ld, C + n1, n2);
    for(int jj = 0; jj < n1; ++jj)
    {
      Scalar* column = block + static_cast<std::size_t>(r[p1 + jj] - first) * static_cast<std::size_t>(rows);
      const Scalar* c = C + static_cast<std::size_t>(jj) * static_cast<std::size_t>(n2);
      for(int ii = jj; ii < n2; ++ii) column[work.position[static_cast<std::size_t>(r[p1 + ii])]] -= c[ii];
    }
  }
}

// Factors the diagonal block of supernode s and solves the rows below with
// it. Returns the column where the matrix showed not to be positive
// definite, or -1.
template <typename Kernels, typename Index, typename Scalar>
std::ptrdiff_t factor_supernode_block(const Supernodal_factor_view<Index, Scalar>& L, Scalar* values, std::size_t s)
{
  const int columns = static_cast<int>(L.super[s + 1] - L.super[s]);
  const int rows = static_cast<int>(L.row_start[s + 1] - L.row_start[s]), below = rows - columns;
  Scalar* block = values + L.value_start[s];
  const int info = Kernels::cholesky_lower(columns, block, rows);
  if(info != 0) return static_cast<std::ptrdiff_t>(L.super[s]) + (info > 0 ? info - 1 : 0);
  if(below > 0) Kernels::solve_with_adjoint_on_right(below, columns, block, rows, block + columns, rows);
  return -1;
}

template <typename Kernels, typename Index, typename Scalar>
std::ptrdiff_t factor_supernode(const Supernodal_factor_view<Index, Scalar>& L, Scalar* values,
                                const Eigen::SparseMatrix<Scalar>& lower, const Supernodal_updates<Index>& updates,
                                std::size_t s, Supernode_workspace<Index, Scalar>& work)
{
  assemble_supernode(L, values, lower, s, work);
  apply_updates<Kernels>(L, values, updates, s, work);
  return factor_supernode_block<Kernels>(L, values, s);
}

// Factors P A P^T = L L^* into `values` (the factor's layout in L, whose
// own values are not read), `lower` being the lower triangle of P A P^T,
// with the kernels Top_kernels for the top of the tree and Subtree_kernels in
// the subtrees. Returns -1, or a column where P A P^T showed not to be
// positive definite (the factor is then unusable). Throws
// Computation_interrupted when the check installed on the calling thread
// asks to stop (interruption.h).
template <typename Top_kernels, typename Subtree_kernels, typename Index, typename Scalar>
std::ptrdiff_t supernodal_factorize_with(const Supernodal_factor_view<Index, Scalar>& L, Scalar* values,
                                         const Eigen::SparseMatrix<Scalar>& lower, const Supernodal_updates<Index>& updates,
                                         const Supernodal_solve_plan& plan)
{
  const std::vector<Supernodal_solve_plan::Task>& tasks = plan.tasks();
  // the heaviest subtrees first, for a balanced end (the order changes no result)
  std::vector<double> work(tasks.size(), 0.);
  for(std::size_t t = 0; t < tasks.size(); ++t)
    for(std::size_t s = tasks[t].first; s <= tasks[t].last; ++s)
    {
      const double columns = static_cast<double>(L.super[s + 1] - L.super[s]);
      const double rows = static_cast<double>(L.row_start[s + 1] - L.row_start[s]);
      work[t] += columns * rows * rows;
    }
  std::vector<std::size_t> order(tasks.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&work](std::size_t a, std::size_t b) { return work[a] > work[b]; });

  // One factorization with the BLAS at a time in the process: OpenBLAS's
  // number of threads is process-wide, and the top of this tree must find the
  // number it had before any subtree phase (Single_threaded_blas), so that
  // the digits do not depend on what else runs. The loops run isolated: a
  // thread waiting for them must not start another factorization meanwhile.
  std::unique_lock<std::mutex> exclusive(blas_factorization_lock(), std::defer_lock);
  if(std::is_same<Top_kernels, Dense_kernels<typename Scalar::value_type> >::value) exclusive.lock();
  std::ptrdiff_t failed = -1;
  Interruption_poll poll;
  isolated([&] {
    std::atomic<std::ptrdiff_t> failed_column(-1);
    {
      std::unique_ptr<Single_threaded_blas> one_thread_each;
      if(std::is_same<Subtree_kernels, Dense_kernels<typename Scalar::value_type> >::value)
        one_thread_each = std::make_unique<Single_threaded_blas>();
      parallel_for_each_task(tasks.size(), [&](std::size_t i) {
        const Subnormals_flushed_in_scope<Scalar> flushed;  // on this task's thread (subnormals.h)
        const Supernodal_solve_plan::Task& task = tasks[order[i]];
        Supernode_workspace<Index, Scalar> workspace(L.n);
        for(std::size_t s = task.first; s <= task.last && failed_column.load() < 0 && !poll.stopped(); ++s)
        {
          const std::ptrdiff_t column = factor_supernode<Subtree_kernels>(L, values, lower, updates, s, workspace);
          if(column >= 0) failed_column.store(column);
        }
      });
    }
    failed = failed_column.load();
    const Subnormals_flushed_in_scope<Scalar> flushed;
    // The flush reaches no thread of OpenBLAS's own (no public call sets their floating-point mode): where the
    // package controls OpenBLAS's threads, the top of a single-precision factor runs on the calling thread.
    std::unique_ptr<Single_threaded_blas> flushed_top;
    if(Subnormals_flushed_in_scope<Scalar>::flushes() &&
       std::is_same<Top_kernels, Dense_kernels<typename Scalar::value_type> >::value && controls_blas_threads())
      flushed_top = std::make_unique<Single_threaded_blas>();
    Supernode_workspace<Index, Scalar> workspace(L.n);
    for(auto s = plan.top().begin(); s != plan.top().end() && failed < 0 && !poll.stopped(); ++s)
      failed = factor_supernode<Top_kernels>(L, values, lower, updates, *s, workspace);
  });
  poll.throw_if_stopped();
  return failed;
}

// The same with the kernels of dense_kernels.h: the BLAS at the top and,
// where the user let the package keep OpenBLAS to one thread, in the
// subtrees (Eigen's there otherwise); Eigen's everywhere if `use_blas` is
// false or the BLAS is not linked.
template <typename Index, typename Scalar>
std::ptrdiff_t supernodal_factorize(const Supernodal_factor_view<Index, Scalar>& L, Scalar* values,
                                    const Eigen::SparseMatrix<Scalar>& lower, const Supernodal_updates<Index>& updates,
                                    const Supernodal_solve_plan& plan, bool use_blas = true)
{
  typedef typename Scalar::value_type Real;
  typedef Eigen_dense_kernels<Real> Eigen_kernels;
  typedef std::conditional_t<has_dense_kernels, Dense_kernels<Real>, Eigen_kernels> Top_kernels;
  typedef std::conditional_t<can_control_blas_threads, Dense_kernels<Real>, Eigen_kernels> Controlled_kernels;
  if(!use_blas)
    return supernodal_factorize_with<Eigen_kernels, Eigen_kernels>(L, values, lower, updates, plan);
  if(controls_blas_threads())
    return supernodal_factorize_with<Top_kernels, Controlled_kernels>(L, values, lower, updates, plan);
  return supernodal_factorize_with<Top_kernels, Eigen_kernels>(L, values, lower, updates, plan);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_SUPERNODAL_FACTORIZATION_H
