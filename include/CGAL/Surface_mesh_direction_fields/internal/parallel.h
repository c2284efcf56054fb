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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PARALLEL_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PARALLEL_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#endif

// Loops over independent indices: in parallel with TBB when CGAL is linked
// with it (the CMake target CGAL::TBB_support defines CGAL_LINKED_WITH_TBB),
// sequential otherwise. Each index must write only to its own outputs.
// Defining CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEQUENTIAL forces sequential loops.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Below this many items a loop is not worth distributing.
constexpr std::size_t parallel_grain_size = 4096;

// body(begin, end) on consecutive sub-ranges of [0, n): lets each chunk keep
// its own scratch buffers.
template <typename RangeBody>
void parallel_for_each_range(std::size_t n, const RangeBody& body)
{
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEQUENTIAL)
  if(n > parallel_grain_size)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, parallel_grain_size),
                      [&body](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
    return;
  }
#endif
  body(std::size_t(0), n);
}

template <typename IndexBody>
void parallel_for_each_index(std::size_t n, const IndexBody& body)
{
  parallel_for_each_range(n, [&body](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i) body(i);
  });
}

// body(i) for each of a few heavy, independent items i in [0, n) (one
// item per task, unlike parallel_for_each_index()).
template <typename IndexBody>
void parallel_for_each_task(std::size_t n, const IndexBody& body)
{
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEQUENTIAL)
  if(n > 1)
  {
    tbb::parallel_for(std::size_t(0), n, [&body](std::size_t i) { body(i); });
    return;
  }
#endif
  for(std::size_t i = 0; i < n; ++i) body(i);
}

// body(begin, end) on the fixed chunks [k g, (k + 1) g) of [0, n), g =
// `parallel_grain_size`, in parallel: unlike parallel_for_each_range(), the
// chunks do not depend on the scheduling, so neither does a result computed
// chunk by chunk (a block product, for instance).
template <typename ChunkBody>
void parallel_for_each_chunk(std::size_t n, const ChunkBody& body)
{
  const std::size_t chunks = (n + parallel_grain_size - 1) / parallel_grain_size;
  auto run_chunk = [&](std::size_t k) { body(k * parallel_grain_size, (std::min)(n, (k + 1) * parallel_grain_size)); };
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEQUENTIAL)
  if(chunks > 1)
  {
    tbb::parallel_for(std::size_t(0), chunks, run_chunk);
    return;
  }
#endif
  for(std::size_t k = 0; k < chunks; ++k) run_chunk(k);
}

// first() and second(), two independent pieces of work, at the same time
// when TBB is available (each may run parallel loops of its own: the thread
// that finishes first joins the other's loops); one after the other otherwise.
// Each catches its own exception, and the first one's is rethrown once both
// have finished: an exception reaching TBB would cancel the other's nested
// parallel loops, which then return with part of their iterations not run
// (out of memory in one used to crash the other on half-built data).
// f() on this thread, which meanwhile runs only the tasks f() spawns: a
// thread that holds a lock while its loop runs must not pick up, from
// outside, work that takes the same lock.
template <typename F>
void isolated(const F& f)
{
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEQUENTIAL)
  tbb::this_task_arena::isolate(f);
#else
  f();
#endif
}

template <typename First, typename Second>
void parallel_invoke(const First& first, const Second& second)
{
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEQUENTIAL)
  std::exception_ptr first_error, second_error;
  tbb::parallel_invoke(
    [&] {
      try { first(); }
      catch(...) { first_error = std::current_exception(); }
    },
    [&] {
      try { second(); }
      catch(...) { second_error = std::current_exception(); }
    });
  if(first_error) std::rethrow_exception(first_error);
  if(second_error) std::rethrow_exception(second_error);
#else
  first();
  second();
#endif
}

// A reduction over [0, n) whose result does not depend on the number of
// threads: `chunk_value(begin, end)` reduces fixed chunks of
// `parallel_grain_size` indices (in parallel), then `combine` folds the
// chunks' values in their order. For sums of doubles, this makes the rounding
// the same on every machine and thread count.
template <typename T, typename ChunkValue, typename Combine>
T parallel_reduce_in_order(std::size_t n, T initial, const ChunkValue& chunk_value, const Combine& combine)
{
  const std::size_t chunks = (n + parallel_grain_size - 1) / parallel_grain_size;
  std::vector<T> values(chunks, initial);
  parallel_for_each_chunk(n, [&](std::size_t begin, std::size_t end) {
    values[begin / parallel_grain_size] = chunk_value(begin, end);
  });
  T result = initial;
  for(const T& value : values) result = combine(result, value);
  return result;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PARALLEL_H
