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

#include <cstddef>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
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

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PARALLEL_H
