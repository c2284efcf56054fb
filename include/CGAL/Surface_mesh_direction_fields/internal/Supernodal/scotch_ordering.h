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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_SCOTCH_ORDERING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_SCOTCH_ORDERING_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <cholmod.h>

#include <cstddef>
#include <cstdio>
#include <new>
#include <stdexcept>
#include <vector>

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_SCOTCH
#include <scotch.h>
#endif

// The fill-reducing ordering of large matrices: Scotch's nested dissection
// for the separators, then CAMD within each of its blocks.
//
// On a surface mesh of a million rows and more, METIS's nested dissection is
// half of a first field. Scotch finds its separators in about half that
// time, and CAMD, which then orders the rows of each block by approximate
// minimum degree on the whole matrix (constrained to keep the blocks in
// Scotch's order), brings the factor within a few percent of METIS's
// entries; the measurements are in the benchmark's README. Scotch draws its
// random numbers from a context of its own, seeded here: the ordering is
// the same on every call, also on several threads at once, without the METIS
// lock (ordering_lock.h), and on every machine (Scotch runs on a fixed
// number of threads of its own).
//
// Every status Scotch and CHOLMOD report is checked; a failure of Scotch
// returns an empty ordering and the caller orders with METIS instead.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_SCOTCH

constexpr bool scotch_ordering_available = true;

// The graph of a symmetric matrix given by its lower triangle (CHOLMOD's
// packed columns, rows >= column): both directions of every off-diagonal
// entry, in Scotch's compressed arrays.
struct Symmetric_graph
{
  std::vector<SCOTCH_Num> offsets;    // size n + 1
  std::vector<SCOTCH_Num> neighbors;  // size 2 (off-diagonal entries)
};

inline Symmetric_graph graph_of_lower_triangle(const cholmod_sparse& lower)
{
  const std::size_t n = lower.ncol;
  const int* p = static_cast<const int*>(lower.p);
  const int* i = static_cast<const int*>(lower.i);
  Symmetric_graph g;
  g.offsets.assign(n + 1, 0);
  for(std::size_t col = 0; col < n; ++col)
    for(int k = p[col]; k < p[col + 1]; ++k)
      if(static_cast<std::size_t>(i[k]) != col)
      {
        ++g.offsets[static_cast<std::size_t>(i[k]) + 1];
        ++g.offsets[col + 1];
      }
  for(std::size_t v = 0; v < n; ++v) g.offsets[v + 1] += g.offsets[v];
  g.neighbors.resize(static_cast<std::size_t>(g.offsets[n]));
  std::vector<SCOTCH_Num> next(g.offsets.begin(), g.offsets.end() - 1);
  for(std::size_t col = 0; col < n; ++col)
    for(int k = p[col]; k < p[col + 1]; ++k)
      if(static_cast<std::size_t>(i[k]) != col)
      {
        const std::size_t row = static_cast<std::size_t>(i[k]);
        g.neighbors[static_cast<std::size_t>(next[row]++)] = static_cast<SCOTCH_Num>(col);
        g.neighbors[static_cast<std::size_t>(next[col]++)] = static_cast<SCOTCH_Num>(row);
      }
  return g;
}

// Scotch's objects of one ordering, released in the reverse order of their
// initialization whatever happens.
class Scotch_ordering_session
{
  SCOTCH_Graph m_graph, m_bound_graph;
  SCOTCH_Context m_context;
  SCOTCH_Strat m_strategy;
  bool m_graph_ready = false, m_context_ready = false, m_bound_ready = false, m_strategy_ready = false;

public:
  // Scotch's threads for one ordering. Its separators depend on how many
  // threads find them, even in its deterministic mode, and by default it
  // starts one per core of the machine (or as many as the environment
  // variable SCOTCH_PTHREAD_NUMBER says): the ordering, and with it the
  // field's last digits, would change from one machine to another. A fixed
  // count keeps them; two threads take half of one thread's time on a
  // two-core machine (the benchmark's README).
  static constexpr int thread_count = 2;

  Scotch_ordering_session() = default;
  Scotch_ordering_session(const Scotch_ordering_session&) = delete;
  Scotch_ordering_session& operator=(const Scotch_ordering_session&) = delete;
  ~Scotch_ordering_session()
  {
    if(m_strategy_ready) SCOTCH_stratExit(&m_strategy);
    if(m_bound_ready) SCOTCH_graphExit(&m_bound_graph);
    if(m_context_ready) SCOTCH_contextExit(&m_context);
    if(m_graph_ready) SCOTCH_graphExit(&m_graph);
  }

  // Separators down to parts of about 240 rows, each found on a graph
  // coarsened to about 200 vertices by greedy growing and refined by
  // Fiduccia-Mattheyses with 20% imbalance allowed (PaStiX's strategy for
  // Scotch, with larger parts); the parts and separators are left unordered
  // (`s`), since CAMD orders them after. Smaller parts ordered by Scotch took
  // longer for a larger factor, larger parts gave a larger factor (the
  // benchmark's README).
  static const char* strategy()
  {
    return "c{rat=0.7,cpr=n{sep=/(vert>240)?m{rat=0.8,vert=200,low=h{pass=10},asc=f{bal=0.2}};,ole=s,ose=s},"
           "unc=n{sep=/(vert>240)?m{rat=0.8,vert=200,low=h{pass=10},asc=f{bal=0.2}};,ole=s,ose=s}}";
  }

  // The blocks of Scotch's nested dissection, in elimination order: the
  // rows eliminated k-th for k in [range[b], range[b + 1]) form block b, and
  // rows[k] is the row eliminated k-th; false if Scotch failed.
  bool order(Symmetric_graph& g, std::vector<SCOTCH_Num>& rows, std::vector<SCOTCH_Num>& range)
  {
    const SCOTCH_Num n = static_cast<SCOTCH_Num>(g.offsets.size() - 1);
    if(SCOTCH_graphInit(&m_graph) != 0) return false;
    m_graph_ready = true;
    if(SCOTCH_graphBuild(&m_graph, 0, n, g.offsets.data(), nullptr, nullptr, nullptr,
                         static_cast<SCOTCH_Num>(g.neighbors.size()), g.neighbors.data(), nullptr) != 0)
      return false;
    if(SCOTCH_contextInit(&m_context) != 0) return false;
    m_context_ready = true;
    if(SCOTCH_contextThreadSpawn(&m_context, thread_count, nullptr) != 0) return false;
    if(SCOTCH_contextOptionSetNum(&m_context, SCOTCH_OPTIONNUMDETERMINISTIC, 1) != 0) return false;
    // a generator of the context's own (a context shares Scotch's global
    // one until it is cloned), seeded alike on every call
    if(SCOTCH_contextRandomClone(&m_context) != 0) return false;
    SCOTCH_contextRandomSeed(&m_context, 1);
    if(SCOTCH_graphInit(&m_bound_graph) != 0) return false;
    m_bound_ready = true;
    if(SCOTCH_contextBindGraph(&m_context, &m_graph, &m_bound_graph) != 0) return false;
    if(SCOTCH_stratInit(&m_strategy) != 0) return false;
    m_strategy_ready = true;
    if(SCOTCH_stratGraphOrder(&m_strategy, strategy()) != 0) return false;
    SCOTCH_Num blocks = 0;
    rows.resize(static_cast<std::size_t>(n));
    range.resize(static_cast<std::size_t>(n) + 1);
    // Scotch's direct permutation (the position of each row) is not needed:
    // a null pointer asks for the inverse one (`rows`) only.
    if(SCOTCH_graphOrder(&m_bound_graph, &m_strategy, nullptr, rows.data(), &blocks, range.data(), nullptr) != 0)
      return false;
    range.resize(static_cast<std::size_t>(blocks) + 1);
    return true;
  }
};

// The ordering of the matrix whose lower triangle `lower` is (CHOLMOD's
// Perm: perm[k] is the row eliminated k-th), or an empty vector if Scotch
// failed. CHOLMOD's failures throw (as `check` does with its status).
template <typename Check>
std::vector<int> scotch_camd_ordering(cholmod_sparse& lower, cholmod_common& common, const Check& check)
{
  std::vector<SCOTCH_Num> rows, range;
  {
    Symmetric_graph g = graph_of_lower_triangle(lower);
    Scotch_ordering_session session;
    if(!session.order(g, rows, range)) return {};
  }
  // CAMD keeps the blocks in Scotch's order (children before their
  // separator) and orders the rows within each by minimum degree.
  std::vector<int> block_of_row(rows.size());
  for(std::size_t b = 0; b + 1 < range.size(); ++b)
    for(SCOTCH_Num k = range[b]; k < range[b + 1]; ++k)
      block_of_row[static_cast<std::size_t>(rows[static_cast<std::size_t>(k)])] = static_cast<int>(b);
  std::vector<SCOTCH_Num>().swap(rows);
  std::vector<int> perm(block_of_row.size());
  const int ok = cholmod_camd(&lower, nullptr, 0, block_of_row.data(), perm.data(), &common);
  check(ok != 0, "ordering the matrix (CAMD)");
  return perm;
}

#else

constexpr bool scotch_ordering_available = false;

template <typename Check>
std::vector<int> scotch_camd_ordering(cholmod_sparse&, cholmod_common&, const Check&)
{
  return {};
}

#endif

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUPERNODAL_SCOTCH_ORDERING_H
