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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PREFETCH_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PREFETCH_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/use.h>

#include <cstddef>

// Software prefetching: a hint that asks the processor to start loading a
// cache line that will be read soon, and changes nothing else (it compiles to
// nothing on compilers without __builtin_prefetch).
//
// Why: the loops over faces read data of each face's three vertices (points,
// angles), and the loops over vertices read data of each vertex's faces;
// these lie anywhere in memory on meshes whose element order has little
// locality (Loop subdivision appends the edge midpoints), so the loops wait
// on memory rather than compute. Asking for the data of an element a few
// steps ahead overlaps those waits (the gain on the local matrices and the
// gathering of A and M is in the benchmark's README).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// How many elements ahead a loop asks for its data: far enough for a load
// from memory to arrive, near enough for the line to be still in cache.
constexpr std::size_t prefetch_distance = 8;

inline void prefetch_address(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  CGAL_USE(p);
#endif
}

// The cache lines of [begin, begin + bytes).
inline void prefetch_range(const void* begin, std::size_t bytes)
{
  const char* p = static_cast<const char*>(begin);
  for(std::size_t offset = 0; offset < bytes; offset += 64) prefetch_address(p + offset);
  if(bytes > 0) prefetch_address(p + bytes - 1);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PREFETCH_H
