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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_SUPERNODAL_SOLVE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_SUPERNODAL_SOLVE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/prefetch.h>
#include <CGAL/use.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <queue>
#include <type_traits>
#include <utility>
#include <vector>

// Solves with a supernodal Cholesky factor P A P^T = L L^* (CHOLMOD's
// layout, read in place), the subtrees of its elimination tree in parallel.
//
// CHOLMOD's own solve runs one supernode after the other, in BLAS level 2,
// and is single-threaded for one right-hand side (two independent solves on
// two cores take barely longer than one: memory bandwidth is not what limits
// it). The supernodes of disjoint subtrees are
// independent, except that a subtree's forward solve subtracts from the
// unknowns of its ancestors. The tree is therefore cut into a "top" (the
// ancestors) and independent subtrees ("tasks") of bounded work; each task
// collects its updates of top unknowns in its own buffer, the buffers are
// added in task order (so the result does not depend on the scheduling),
// then the top is solved supernode after supernode, its large supernodes
// split over the threads in fixed chunks. The backward solve reads only
// ancestors, so it needs no buffer: top first, then the tasks in parallel.
//
// The factor is described by plain arrays (as in `cholmod_factor`):
// supernode s has the columns [super[s], super[s+1]), the row indices
// rows[row_start[s] .. row_start[s+1]) (its own columns first), and its
// entries as a dense column-major block at values + value_start[s], with
// leading dimension row_start[s+1] - row_start[s]. Supernodes are numbered in
// a postorder of the tree (CHOLMOD's default), so every subtree is a range
// of consecutive supernodes.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The factor's entries are std::complex<double>, or std::complex<float> for
// a factor computed in single precision.
template <typename Index, typename Scalar = std::complex<double> >
struct Supernodal_factor_view
{
  std::size_t n = 0, supernodes = 0;
  const Index* super = nullptr;        // supernodes + 1 column boundaries
  const Index* row_start = nullptr;    // supernodes + 1 offsets into rows
  const Index* rows = nullptr;
  const Index* value_start = nullptr;  // supernodes + 1 offsets into values
  const Scalar* values = nullptr;
  const Index* permutation = nullptr;  // row k of P A P^T is row permutation[k] of A (null: identity)
};

// The supernode that holds each column of the factor.
template <typename Index, typename Scalar>
std::vector<std::size_t> supernode_of_each_column(const Supernodal_factor_view<Index, Scalar>& L)
{
  std::vector<std::size_t> supernode_of_column(L.n);
  for(std::size_t s = 0; s < L.supernodes; ++s)
    for(std::size_t j = static_cast<std::size_t>(L.super[s]); j < static_cast<std::size_t>(L.super[s + 1]); ++j)
      supernode_of_column[j] = s;
  return supernode_of_column;
}

// The cut of the tree, computed once per symbolic structure: subtrees of at
// most 1 / `task_budget` of the factor's entries each, the rest is the top.
// The budget is fixed, not taken from the number of threads, because the cut
// decides the order of the additions: with a fixed cut the solution is the
// same bit for bit on every machine.
class Supernodal_solve_plan
{
public:
  struct Task
  {
    std::size_t first, last;  // supernodes [first, last], a whole subtree
  };

  template <typename Index, typename Scalar>
  explicit Supernodal_solve_plan(const Supernodal_factor_view<Index, Scalar>& L, std::size_t task_budget = 16)
  {
    const Tree tree = read_tree(L);
    m_valid = tree.postordered;
    if(!m_valid) return;
    cut(L, tree, task_budget);
    m_valid = tasks_touch_only_the_top(L);
  }

  bool valid() const { return m_valid; }
  const std::vector<Task>& tasks() const { return m_tasks; }
  const std::vector<std::size_t>& top() const { return m_top; }
  const std::vector<std::size_t>& top_columns() const { return m_top_columns; }
  std::int32_t top_position(std::size_t column) const { return m_top_position[column]; }

private:
  static constexpr std::size_t none = std::size_t(-1);

  struct Tree
  {
    std::vector<std::size_t> parent, first_descendant;
    std::vector<double> subtree_work;  // entries of the factor in the subtree
    bool postordered = true;
  };

  // The supernodal elimination tree: the parent of a supernode holds the
  // first row below its diagonal block.
  template <typename Index, typename Scalar>
  static Tree read_tree(const Supernodal_factor_view<Index, Scalar>& L)
  {
    const std::size_t ns = L.supernodes;
    const std::vector<std::size_t> supernode_of_column = supernode_of_each_column(L);
    Tree tree;
    tree.parent.assign(ns, none);
    tree.first_descendant.resize(ns);
    tree.subtree_work.resize(ns);
    for(std::size_t s = 0; s < ns; ++s)
    {
      const Index columns = L.super[s + 1] - L.super[s], rows = L.row_start[s + 1] - L.row_start[s];
      if(rows > columns)
        tree.parent[s] = supernode_of_column[static_cast<std::size_t>(L.rows[L.row_start[s] + columns])];
      tree.first_descendant[s] = s;
      tree.subtree_work[s] = static_cast<double>(rows) * static_cast<double>(columns);
    }
    for(std::size_t s = 0; s < ns; ++s)  // postorder: children before their parent
    {
      const std::size_t p = tree.parent[s];
      if(p == none) continue;
      if(p <= s)
      {
        tree.postordered = false;
        break;
      }
      tree.subtree_work[p] += tree.subtree_work[s];
      tree.first_descendant[p] = (std::min)(tree.first_descendant[p], tree.first_descendant[s]);
    }
    return tree;
  }

  // Splits the heaviest subtree until each is at most 1 / budget of the
  // whole: the root of a split subtree joins the top, its children become
  // subtrees.
  template <typename Index, typename Scalar>
  void cut(const Supernodal_factor_view<Index, Scalar>& L, const Tree& tree, std::size_t task_budget)
  {
    const std::size_t ns = L.supernodes;
    std::vector<std::vector<std::size_t> > children(ns);
    std::vector<std::size_t> roots;
    double total = 0.;
    for(std::size_t s = 0; s < ns; ++s)
    {
      if(tree.parent[s] == none)
      {
        roots.push_back(s);
        total += tree.subtree_work[s];
      }
      else
        children[tree.parent[s]].push_back(s);
    }
    const double largest_task = total / static_cast<double>(task_budget);
    auto lighter = [&tree](std::size_t a, std::size_t b) { return tree.subtree_work[a] < tree.subtree_work[b]; };
    std::priority_queue<std::size_t, std::vector<std::size_t>, decltype(lighter)> heap(lighter, roots);
    std::vector<unsigned char> in_top(ns, 0);
    std::vector<std::size_t> task_roots;
    while(!heap.empty())
    {
      const std::size_t s = heap.top();
      heap.pop();
      if(tree.subtree_work[s] <= largest_task)
        task_roots.push_back(s);
      else
      {
        in_top[s] = 1;
        for(std::size_t c : children[s]) heap.push(c);
      }
    }
    std::sort(task_roots.begin(), task_roots.end());
    for(std::size_t r : task_roots) m_tasks.push_back({tree.first_descendant[r], r});
    for(std::size_t s = 0; s < ns; ++s)
      if(in_top[s]) m_top.push_back(s);
    // the top's columns, numbered for the tasks' buffers
    m_top_position.assign(L.n, -1);
    for(std::size_t s : m_top)
      for(std::size_t j = static_cast<std::size_t>(L.super[s]); j < static_cast<std::size_t>(L.super[s + 1]); ++j)
      {
        m_top_position[j] = static_cast<std::int32_t>(m_top_columns.size());
        m_top_columns.push_back(j);
      }
  }

  // What the solve relies on: every row below a task's supernode is a column
  // of that task or of the top (true of an elimination tree, whose
  // off-diagonal rows are ancestors; checked, since the tree was read from
  // the first of them only).
  template <typename Index, typename Scalar>
  bool tasks_touch_only_the_top(const Supernodal_factor_view<Index, Scalar>& L) const
  {
    for(const Task& task : m_tasks)
    {
      const Index first_column = L.super[task.first], end_column = L.super[task.last + 1];
      for(std::size_t s = task.first; s <= task.last; ++s)
        for(Index p = L.row_start[s] + (L.super[s + 1] - L.super[s]); p < L.row_start[s + 1]; ++p)
        {
          const Index row = L.rows[p];
          if((row < first_column || row >= end_column) && m_top_position[static_cast<std::size_t>(row)] < 0)
            return false;
        }
    }
    return true;
  }

  bool m_valid = false;
  std::vector<Task> m_tasks;
  std::vector<std::size_t> m_top;          // supernodes of the top, increasing
  std::vector<std::size_t> m_top_columns;  // their columns
  std::vector<std::int32_t> m_top_position;
};

// A supernode's stored block of the factor, read in place, and the vectors
// of a solve, in the factor's precision.
template <typename Scalar>
using Supernode_block = Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> >;
template <typename Scalar>
using Solve_vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

template <typename Index, typename Scalar>
Supernode_block<Scalar> supernode_block(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s)
{
  const Eigen::Index rows = static_cast<Eigen::Index>(L.row_start[s + 1] - L.row_start[s]);
  const Eigen::Index columns = static_cast<Eigen::Index>(L.super[s + 1] - L.super[s]);
  return Supernode_block<Scalar>(L.values + L.value_start[s], rows, columns);
}

// The rows below supernode s's diagonal block: y at them, into scratch; and
// each scratch value, with its row, to subtract(row, value).
template <typename Index, typename Scalar>
void gather_below(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s, const Solve_vector<Scalar>& y,
                  Solve_vector<Scalar>& scratch)
{
  const Index columns = L.super[s + 1] - L.super[s];
  const Index* rows = L.rows + L.row_start[s] + columns;
  scratch.resize(L.row_start[s + 1] - L.row_start[s] - columns);
  for(Eigen::Index i = 0; i < scratch.size(); ++i) scratch[i] = y[static_cast<Eigen::Index>(rows[i])];
}

template <typename Index, typename Scalar, typename Subtract>
void scatter_below(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s, const Solve_vector<Scalar>& scratch,
                   const Subtract& subtract)
{
  const Index* rows = L.rows + L.row_start[s] + (L.super[s + 1] - L.super[s]);
  for(Eigen::Index i = 0; i < scratch.size(); ++i) subtract(static_cast<std::size_t>(rows[i]), scratch[i]);
}

// The kernels of the two steps below, on complex numbers stored as pairs of
// reals (the layout std::complex guarantees), in plain loops: on surface
// meshes most supernodes are small, and for them the fixed cost of each call
// into Eigen's triangular solve and matrix-vector product outweighed the work
// (the benchmark's README).
//
// t[i] -= b[i] y for i in [0, count).
template <typename Real>
void subtract_multiple(const std::complex<Real>* b, const std::complex<Real>& y, std::complex<Real>* t,
                       Eigen::Index count)
{
  const Real yr = y.real(), yi = y.imag();
  const Real* bd = reinterpret_cast<const Real*>(b);
  Real* td = reinterpret_cast<Real*>(t);
  for(Eigen::Index i = 0; i < 2 * count; i += 2)
  {
    const Real br = bd[i], bi = bd[i + 1];
    td[i] -= br * yr - bi * yi;
    td[i + 1] -= br * yi + bi * yr;
  }
}

// The sum of conj(b[i]) t[i] for i in [0, count), in four interleaved
// partial sums (independent chains of additions; a fixed order, so the same
// on every machine).
template <typename Real>
std::complex<Real> adjoint_dot(const std::complex<Real>* b, const std::complex<Real>* t, Eigen::Index count)
{
  const Real* bd = reinterpret_cast<const Real*>(b);
  const Real* td = reinterpret_cast<const Real*>(t);
  Real re[4] = {0, 0, 0, 0}, im[4] = {0, 0, 0, 0};
  Eigen::Index i = 0;
  for(; i + 8 <= 2 * count; i += 8)
    for(int k = 0; k < 4; ++k)
    {
      re[k] += bd[i + 2 * k] * td[i + 2 * k] + bd[i + 2 * k + 1] * td[i + 2 * k + 1];
      im[k] += bd[i + 2 * k] * td[i + 2 * k + 1] - bd[i + 2 * k + 1] * td[i + 2 * k];
    }
  for(int k = 0; i < 2 * count; i += 2, ++k)
  {
    re[k] += bd[i] * td[i] + bd[i + 1] * td[i + 1];
    im[k] += bd[i] * td[i + 1] - bd[i + 1] * td[i];
  }
  return std::complex<Real>((re[0] + re[1]) + (re[2] + re[3]), (im[0] + im[1]) + (im[2] + im[3]));
}

// Asks the processor to start loading the entries of supernode s (a hint,
// see prefetch.h). The backward solve walks the supernodes from the last to
// the first, and the hardware prefetcher then lagged behind: asking for the
// next supernode while one is solved makes the backward solve of the
// subtrees faster (the forward solve, which walks up through memory, gains
// nothing from it).
template <typename Index, typename Scalar>
void prefetch_supernode(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s)
{
  const auto* begin = L.values + L.value_start[s];
  prefetch_range(begin, static_cast<std::size_t>(L.value_start[s + 1] - L.value_start[s]) * sizeof(*begin));
}

// Forward step of supernode s on y: solves its diagonal block, then gives
// each row r below it, with the product of that row and the solved part, to
// subtract(r, value). One pass down the block's columns, each read once,
// contiguously: t holds the supernode's unknowns, then (from zero) minus
// the products of the rows below. The diagonal of an LL^* factor is real.
template <typename Index, typename Scalar, typename Subtract>
void forward_supernode(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s, Solve_vector<Scalar>& y,
                       Solve_vector<Scalar>& t, const Subtract& subtract)
{
  const Supernode_block<Scalar> block = supernode_block(L, s);
  const Eigen::Index columns = block.cols(), rows = block.rows();
  const Eigen::Index first = static_cast<Eigen::Index>(L.super[s]);
  t.resize(rows);
  t.head(columns) = y.segment(first, columns);
  t.tail(rows - columns).setZero();
  for(Eigen::Index j = 0; j < columns; ++j)
  {
    const Scalar* column = block.data() + j * rows;
    t[j] /= column[j].real();
    subtract_multiple(column + j + 1, t[j], t.data() + j + 1, rows - j - 1);
  }
  y.segment(first, columns) = t.head(columns);
  const Index* below = L.rows + L.row_start[s] + columns;
  for(Eigen::Index i = columns; i < rows; ++i) subtract(static_cast<std::size_t>(below[i - columns]), -t[i]);
}

// Backward step: y_s <- L_ss^{-*} (y_s - L_below^* y_below). The rows below
// go through Eigen's product (its products with the columns are independent,
// and Eigen interleaves them, which was faster than a loop over the columns
// here); the triangle is solved from the last column up, each column's
// entries read contiguously.
template <typename Index, typename Scalar>
void backward_supernode(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s, Solve_vector<Scalar>& y,
                        Solve_vector<Scalar>& scratch)
{
  const Supernode_block<Scalar> block = supernode_block(L, s);
  const Eigen::Index columns = block.cols(), below = block.rows() - columns;
  const Eigen::Index first = static_cast<Eigen::Index>(L.super[s]);
  auto ys = y.segment(first, columns);
  if(below > 0)
  {
    gather_below(L, s, y, scratch);
    ys.noalias() -= block.bottomRows(below).adjoint() * scratch;
  }
  for(Eigen::Index j = columns; j-- > 0;)
  {
    const Scalar* column = block.data() + j * block.rows();
    ys[j] = (ys[j] - adjoint_dot(column + j + 1, ys.data() + j + 1, columns - j - 1)) / column[j].real();
  }
}

// The same two steps for a large supernode of the top, with its products
// split over threads. The diagonal block is taken in panels of `panel`
// columns: each panel's small triangle is solved, then the rest of the
// supernode is updated with it, in fixed chunks of rows (forward) or of
// columns (backward), so the result does not depend on the scheduling.
constexpr Eigen::Index panel = 64;
constexpr Eigen::Index supernode_chunk_entries = 16384;

template <typename Body>
void for_each_chunk_of(Eigen::Index begin, Eigen::Index end, Eigen::Index chunk, const Body& body)
{
  if(end <= begin) return;
  const std::size_t chunks = static_cast<std::size_t>((end - begin + chunk - 1) / chunk);
  parallel_for_each_task(chunks, [&](std::size_t c) {
    const Eigen::Index a = begin + static_cast<Eigen::Index>(c) * chunk;
    body(a, (std::min)(end, a + chunk));
  });
}

// The triangular solves of one panel of a supernode's diagonal block, in
// place, as plain loops: Eigen's solveInPlace() on std::complex<float> loads
// the scalar through a double pointer (pset1 of its SSE complex packet), an
// access at 4-byte alignment that UndefinedBehaviorSanitizer reports.
// L y = b, L lower triangular:
template <typename Block, typename Vector>
void solve_lower_in_place(const Block& L, Vector&& y)
{
  for(Eigen::Index j = 0; j < L.cols(); ++j)
  {
    const auto yj = y[j] / L(j, j);
    y[j] = yj;
    for(Eigen::Index i = j + 1; i < L.rows(); ++i) y[i] -= L(i, j) * yj;
  }
}
// L^* y = b, L lower triangular (L^* upper):
template <typename Block, typename Vector>
void solve_lower_adjoint_in_place(const Block& L, Vector&& y)
{
  for(Eigen::Index j = L.cols() - 1; j >= 0; --j)
  {
    auto sum = y[j];
    for(Eigen::Index i = j + 1; i < L.rows(); ++i) sum -= std::conj(L(i, j)) * y[i];
    y[j] = sum / std::conj(L(j, j));
  }
}

template <typename Index, typename Scalar, typename Subtract>
void forward_supernode_in_parallel(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s, Solve_vector<Scalar>& y,
                                   Solve_vector<Scalar>& scratch, const Subtract& subtract)
{
  const Supernode_block<Scalar> block = supernode_block(L, s);
  const Eigen::Index columns = block.cols(), rows = block.rows(), below = rows - columns;
  auto ys = y.segment(static_cast<Eigen::Index>(L.super[s]), columns);
  scratch.setZero(below);
  for(Eigen::Index c0 = 0; c0 < columns; c0 += panel)
  {
    const Eigen::Index w = (std::min)(panel, columns - c0);
    solve_lower_in_place(block.block(c0, c0, w, w), ys.segment(c0, w));
    const auto solved = ys.segment(c0, w);
    // rows [c0 + w, rows): the rest of the diagonal block, then the rows below
    for_each_chunk_of(c0 + w, rows, (std::max)(Eigen::Index(64), supernode_chunk_entries / w), [&](Eigen::Index a, Eigen::Index b) {
      const Solve_vector<Scalar> product = block.block(a, c0, b - a, w) * solved;
      for(Eigen::Index i = a; i < b; ++i)
      {
        if(i < columns) ys[i] -= product[i - a];
        else scratch[i - columns] += product[i - a];
      }
    });
  }
  scatter_below(L, s, scratch, subtract);
}

template <typename Index, typename Scalar>
void backward_supernode_in_parallel(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s, Solve_vector<Scalar>& y,
                                    Solve_vector<Scalar>& scratch)
{
  const Supernode_block<Scalar> block = supernode_block(L, s);
  const Eigen::Index columns = block.cols(), below = block.rows() - columns;
  auto ys = y.segment(static_cast<Eigen::Index>(L.super[s]), columns);
  if(below > 0)
  {
    gather_below(L, s, y, scratch);
    for_each_chunk_of(0, columns, (std::max)(Eigen::Index(1), supernode_chunk_entries / below), [&](Eigen::Index a, Eigen::Index b) {
      ys.segment(a, b - a).noalias() -= block.bottomRows(below).middleCols(a, b - a).adjoint() * scratch;
    });
  }
  // L_ss^* is upper triangular: from the last panel up, solve it, then
  // remove its contribution from the columns before it
  for(Eigen::Index end = columns; end > 0;)
  {
    const Eigen::Index c0 = (std::max)(Eigen::Index(0), end - panel), w = end - c0;
    solve_lower_adjoint_in_place(block.block(c0, c0, w, w), ys.segment(c0, w));
    const Solve_vector<Scalar> solved = ys.segment(c0, w);
    for_each_chunk_of(0, c0, (std::max)(Eigen::Index(1), supernode_chunk_entries / w), [&](Eigen::Index a, Eigen::Index b) {
      ys.segment(a, b - a).noalias() -= block.block(c0, a, w, b - a).adjoint() * solved;
    });
    end = c0;
  }
}

// Whether a supernode is worth splitting over threads.
inline bool is_large_supernode(Eigen::Index rows, Eigen::Index columns) { return rows * columns >= 4 * supernode_chunk_entries; }

template <typename Index, typename Scalar, typename Subtract>
void forward_top_supernode(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s, Solve_vector<Scalar>& y,
                           Solve_vector<Scalar>& scratch, const Subtract& subtract)
{
  const Supernode_block<Scalar> block = supernode_block(L, s);
  if(is_large_supernode(block.rows(), block.cols())) forward_supernode_in_parallel(L, s, y, scratch, subtract);
  else forward_supernode(L, s, y, scratch, subtract);
}

template <typename Index, typename Scalar>
void backward_top_supernode(const Supernodal_factor_view<Index, Scalar>& L, std::size_t s, Solve_vector<Scalar>& y,
                            Solve_vector<Scalar>& scratch)
{
  const Supernode_block<Scalar> block = supernode_block(L, s);
  if(is_large_supernode(block.rows(), block.cols())) backward_supernode_in_parallel(L, s, y, scratch);
  else backward_supernode(L, s, y, scratch);
}


// y <- (L L^*)^{-1} y, in the permuted numbering.
template <typename Index, typename Scalar>
void solve_permuted(const Supernodal_factor_view<Index, Scalar>& L, const Supernodal_solve_plan& plan,
                    Solve_vector<Scalar>& y)
{
  // forward: the tasks, each with its buffer of updates of the top
  const std::vector<Supernodal_solve_plan::Task>& tasks = plan.tasks();
  const std::vector<std::size_t>& top_columns = plan.top_columns();
  std::vector<Solve_vector<Scalar> > buffers(tasks.size());
  parallel_for_each_task(tasks.size(), [&](std::size_t t) {
    Solve_vector<Scalar>& buffer = buffers[t];
    buffer.setZero(static_cast<Eigen::Index>(top_columns.size()));
    Solve_vector<Scalar> scratch;
    const std::size_t first_column = static_cast<std::size_t>(L.super[tasks[t].first]);
    const std::size_t end_column = static_cast<std::size_t>(L.super[tasks[t].last + 1]);
    for(std::size_t s = tasks[t].first; s <= tasks[t].last; ++s)
      forward_supernode(L, s, y, scratch, [&](std::size_t row, const Scalar& value) {
        if(row >= first_column && row < end_column)
          y[static_cast<Eigen::Index>(row)] -= value;
        else
          buffer[plan.top_position(row)] += value;  // an ancestor: in the top
      });
  });
  for(const Solve_vector<Scalar>& buffer : buffers)  // in task order: deterministic
    for(std::size_t p = 0; p < top_columns.size(); ++p)
      y[static_cast<Eigen::Index>(top_columns[p])] -= buffer[static_cast<Eigen::Index>(p)];
  buffers.clear();
  {
    Solve_vector<Scalar> scratch;
    for(std::size_t s : plan.top())
      forward_top_supernode(L, s, y, scratch, [&](std::size_t row, const Scalar& value) { y[static_cast<Eigen::Index>(row)] -= value; });
    // backward: the top, then the tasks
    for(auto s = plan.top().rbegin(); s != plan.top().rend(); ++s) backward_top_supernode(L, *s, y, scratch);
  }
  parallel_for_each_task(tasks.size(), [&](std::size_t t) {
    Solve_vector<Scalar> scratch;
    for(std::size_t s = tasks[t].last + 1; s-- > tasks[t].first;)
    {
      if(s > tasks[t].first) prefetch_supernode(L, s - 1);
      backward_supernode(L, s, y, scratch);
    }
  });
}

// x = A^{-1} b for P A P^T = L L^*, in double precision whatever the
// factor's. A factor in single precision solves in single precision, on b
// scaled to a largest part of 1: the right-hand sides of the eigen-solve
// are residuals, whose entries can lie far below the smallest float.
template <typename Index, typename Scalar>
Complex_vector supernodal_solve(const Supernodal_factor_view<Index, Scalar>& L, const Supernodal_solve_plan& plan,
                                const Eigen::Ref<const Complex_vector>& b)
{
  const Eigen::Index n = static_cast<Eigen::Index>(L.n);
  auto permuted = [&L](std::size_t i) {
    return static_cast<Eigen::Index>(L.permutation ? static_cast<std::size_t>(L.permutation[i]) : i);
  };
  double scale = 1.;
  if(!std::is_same<Scalar, Complex>::value && n > 0)
  {
    // the largest real or imaginary part: as good a scale as the largest
    // modulus, without its square roots
    const double largest = Eigen::Map<const Eigen::VectorXd>(reinterpret_cast<const double*>(b.data()), 2 * n)
                             .cwiseAbs().maxCoeff();
    if(largest > 0. && std::isfinite(largest)) scale = largest;
  }
  Solve_vector<Scalar> y(n);
  parallel_for_each_index(L.n, [&](std::size_t i) {
    y[static_cast<Eigen::Index>(i)] = Scalar(b[permuted(i)] / scale);
  });
  solve_permuted(L, plan, y);
  Complex_vector x(n);
  parallel_for_each_index(L.n, [&](std::size_t i) {
    x[permuted(i)] = Complex(y[static_cast<Eigen::Index>(i)]) * scale;
  });
  return x;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_SUPERNODAL_SOLVE_H
