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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_COARSE_HIERARCHY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_COARSE_HIERARCHY_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/hermitian_products.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <vector>

// The pieces of one level of a cheap estimate of the smallest eigenpair of
// the pencil (A, M), in the spirit of algebraic multigrid: aggregation, the
// coarse pencil, prolongation and smoothing. The eigen-solve
// (eigen_solve.h) chains levels of them into a start vector and an
// upper bound of lambda_1, with which it shifts its factorization close to
// lambda_1, where inverse iteration converges several times faster.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Vertices grouped into aggregates (a vertex and its neighbours, plus the
// leftovers joined to a neighbouring aggregate); a coarse coefficient x_c
// stands for the fine coefficients x_i = phase_i x_c[aggregate_i], where the
// unit phase_i transports the aggregate's root to i: the fine field is
// locally parallel.
struct Aggregates
{
  std::vector<Eigen::Index> of_vertex;
  Complex_vector phase;
  Eigen::Index count = 0;
};

inline Complex unit(const Complex& z)
{
  const double r = std::abs(z);
  return r > 0. ? z / r : Complex(1., 0.);
}

// The transport comes from the phases of the coupling C = sign M: on
// vertices the mass matrix M (the coupling M_ir = r |t| / 12 is positive up
// to the transport for every non-degenerate face, whereas the cotangent
// weights of A can change sign), on faces, whose M is diagonal, C = -A (the
// dual edges' weights are positive). x_i = unit(C_ir) x_r makes the cross
// term conj(x_i) C_ir x_r positive real.
inline Aggregates aggregate_vertices(const Complex_sparse_matrix& coupling, double sign = 1.)
{
  const Complex_sparse_matrix& M = coupling;
  const Eigen::Index n = M.rows();
  Aggregates g;
  g.of_vertex.assign(static_cast<std::size_t>(n), -1);
  g.phase = Complex_vector::Ones(n);
  // roots: vertices whose neighbours are all free take them
  for(Eigen::Index r = 0; r < n; ++r)
  {
    if(g.of_vertex[r] >= 0) continue;
    bool free = true;
    for(Complex_sparse_matrix::InnerIterator it(M, r); it && free; ++it)
      free = g.of_vertex[static_cast<std::size_t>(it.row())] < 0;
    if(!free) continue;
    const Eigen::Index c = g.count++;
    g.of_vertex[r] = c;
    for(Complex_sparse_matrix::InnerIterator it(M, r); it; ++it)
      if(it.row() != r)
      {
        g.of_vertex[static_cast<std::size_t>(it.row())] = c;
        g.phase[it.row()] = unit(sign * it.value());  // C_ir
      }
  }
  // leftovers: join the aggregate of the most strongly coupled neighbour
  std::vector<Eigen::Index> first_pass = g.of_vertex;
  for(Eigen::Index i = 0; i < n; ++i)
  {
    if(first_pass[i] >= 0) continue;
    // the strongest coupling compared by squared modulus (no square root per neighbour)
    double strongest = -1.;
    Eigen::Index best = -1;
    Complex best_value;
    for(Complex_sparse_matrix::InnerIterator it(M, i); it; ++it)  // M_ji
    {
      const Eigen::Index j = it.row();
      if(j == i || first_pass[static_cast<std::size_t>(j)] < 0 || std::norm(it.value()) <= strongest) continue;
      strongest = std::norm(it.value());
      best = j;
      best_value = sign * it.value();
    }
    if(best >= 0)
    {
      g.of_vertex[i] = first_pass[static_cast<std::size_t>(best)];
      g.phase[i] = std::conj(unit(best_value)) * g.phase[best];  // M_ij = conj(M_ji)
    }
    else
      g.of_vertex[i] = g.count++;  // cannot happen: a free vertex with free neighbours is a root
  }
  return g;
}

// The members of each aggregate, contiguous (a counting sort): those of
// aggregate c are members[first[c]] to members[first[c + 1] - 1], in vertex order.
inline void aggregate_members(const Aggregates& g, std::vector<Eigen::Index>& first, std::vector<Eigen::Index>& members)
{
  first.assign(static_cast<std::size_t>(g.count) + 1, 0);
  members.resize(g.of_vertex.size());
  for(Eigen::Index c : g.of_vertex) ++first[static_cast<std::size_t>(c) + 1];
  for(std::size_t c = 0; c < static_cast<std::size_t>(g.count); ++c) first[c + 1] += first[c];
  std::vector<Eigen::Index> fill(first.begin(), first.end() - 1);
  for(std::size_t i = 0; i < g.of_vertex.size(); ++i)
    members[static_cast<std::size_t>(fill[static_cast<std::size_t>(g.of_vertex[i])]++)] = static_cast<Eigen::Index>(i);
}

// The coarse pencil (P^* A P, P^* M P) for the prolongation P of the
// aggregates, (P x_c)_i = phase_i x_c[aggregate_i]: a Rayleigh-Ritz (Galerkin)
// projection, so its smallest eigenvalue bounds lambda_1 from above. Built
// column by column straight into compressed storage (A and M have the same
// pattern, so both coarse matrices share one), in one pass over A's entries;
// fixed chunks of coarse columns are built in parallel, then copied in
// place (each column's entries are sorted by row, so the result does not
// depend on the chunks).
inline void restrict_to_aggregates(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                   const Aggregates& g, Complex_sparse_matrix& Ac, Complex_sparse_matrix& Mc)
{
  typedef Complex_sparse_matrix::StorageIndex Storage_index;
  const Eigen::Index nc = g.count;
  std::vector<Eigen::Index> first, members;
  aggregate_members(g, first, members);

  struct Entry
  {
    Storage_index row;
    Complex a, m;
  };
  const std::size_t chunks = (static_cast<std::size_t>(nc) + parallel_grain_size - 1) / parallel_grain_size;
  std::vector<std::vector<Entry> > chunk_entries(chunks);
  std::vector<Storage_index> column_size(static_cast<std::size_t>(nc), 0);
  const Storage_index* a_outer = A.outerIndexPtr();
  const Storage_index* a_inner = A.innerIndexPtr();
  const Complex* a_value = A.valuePtr();
  const Complex* m_value = M.valuePtr();
  parallel_for_each_chunk(static_cast<std::size_t>(nc), [&](std::size_t begin, std::size_t end) {
    std::vector<Entry>& entries = chunk_entries[begin / parallel_grain_size];
    std::vector<std::size_t> slot(static_cast<std::size_t>(nc), std::size_t(-1));  // of a coarse row in the current column
    for(std::size_t cj = begin; cj < end; ++cj)
    {
      const std::size_t column_begin = entries.size();
      for(Eigen::Index k = first[cj]; k < first[cj + 1]; ++k)
      {
        const Eigen::Index j = members[static_cast<std::size_t>(k)];
        const Complex pj = g.phase[j];
        for(Storage_index p = a_outer[j]; p < a_outer[j + 1]; ++p)
        {
          const Eigen::Index i = a_inner[p];
          const std::size_t ci = static_cast<std::size_t>(g.of_vertex[static_cast<std::size_t>(i)]);
          if(slot[ci] == std::size_t(-1))
          {
            slot[ci] = entries.size();
            entries.push_back({static_cast<Storage_index>(ci), Complex(0., 0.), Complex(0., 0.)});
          }
          const Complex weight = std::conj(g.phase[i]) * pj;
          entries[slot[ci]].a += weight * a_value[p];
          entries[slot[ci]].m += weight * m_value[p];
        }
      }
      std::sort(entries.begin() + static_cast<std::ptrdiff_t>(column_begin), entries.end(),
                [](const Entry& x, const Entry& y) { return x.row < y.row; });
      for(std::size_t e = column_begin; e < entries.size(); ++e) slot[static_cast<std::size_t>(entries[e].row)] = std::size_t(-1);
      column_size[cj] = static_cast<Storage_index>(entries.size() - column_begin);
    }
  });
  std::vector<std::size_t> chunk_offset(chunks + 1, 0);
  for(std::size_t c = 0; c < chunks; ++c) chunk_offset[c + 1] = chunk_offset[c] + chunk_entries[c].size();
  const std::size_t nnz = chunk_offset[chunks];
  for(Complex_sparse_matrix* C : {&Ac, &Mc})
  {
    C->resize(nc, nc);
    C->resizeNonZeros(static_cast<Eigen::Index>(nnz));
    Storage_index* outer = C->outerIndexPtr();
    outer[0] = 0;
    for(std::size_t cj = 0; cj < static_cast<std::size_t>(nc); ++cj) outer[cj + 1] = outer[cj] + column_size[cj];
  }
  parallel_for_each_task(chunks, [&](std::size_t c) {
    const std::vector<Entry>& entries = chunk_entries[c];
    for(std::size_t e = 0, p = chunk_offset[c]; e < entries.size(); ++e, ++p)
    {
      Ac.innerIndexPtr()[p] = Mc.innerIndexPtr()[p] = entries[e].row;
      Ac.valuePtr()[p] = entries[e].a;
      Mc.valuePtr()[p] = entries[e].m;
    }
  });
}

inline Complex_vector prolongate(const Complex_vector& xc, const Aggregates& g)
{
  Complex_vector x(static_cast<Eigen::Index>(g.of_vertex.size()));
  for(Eigen::Index i = 0; i < x.size(); ++i) x[i] = g.phase[i] * xc[g.of_vertex[static_cast<std::size_t>(i)]];
  return x;
}

// Damped Jacobi sweeps on (A - theta M) x = 0, theta the current Rayleigh
// quotient: they remove the jumps a prolongated coarse vector has across the
// aggregates' borders (rough components, which are what makes its Rayleigh
// quotient a poor bound); returns the Rayleigh quotient of the result, an
// upper bound of lambda_1 (none if x vanished). A and M must have the same
// pattern.
inline std::optional<double> smooth_and_bound(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, int sweeps, Complex_vector& x)
{
  const Eigen::VectorXd a_diagonal = A.diagonal().real(), m_diagonal = M.diagonal().real();
  Complex_dense_matrix X(x.size(), 1), AX, MX;
  double theta = 0.;
  for(int sweep = 0;; ++sweep)
  {
    X.col(0) = x;
    hermitian_multiply_pair(A, M, true, X, AX, MX);
    const double norm2 = x.dot(MX.col(0)).real();
    if(!(norm2 > 0.)) return std::nullopt;
    theta = x.dot(AX.col(0)).real() / norm2;
    if(sweep == sweeps) break;
    for(Eigen::Index i = 0; i < x.size(); ++i)
    {
      const double d = a_diagonal[i] - theta * m_diagonal[i];
      if(d > 0.) x[i] -= (2. / 3.) * (AX(i, 0) - theta * MX(i, 0)) / d;
    }
  }
  return theta;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_COARSE_HIERARCHY_H
