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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_HUGE_PAGES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_HUGE_PAGES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <cstddef>
#include <cstdint>

#if defined(__linux__) && !defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_NO_HUGE_PAGES)
#include <sys/mman.h>
#endif

// Transparent huge pages for the package's own large buffers.
//
// The first write to a fresh 4 KB page costs a page fault, and on virtual
// machines faults can cost more than the arithmetic that fills the page (the
// benchmark's README has the numbers). A 2 MB huge page costs one fault.
// Linux grants huge pages to a range advised with MADV_HUGEPAGE when the
// system setting (/sys/kernel/mm/transparent_hugepage/enabled) is `madvise`
// or `always`; elsewhere, or with
// CGAL_SURFACE_MESH_DIRECTION_FIELDS_NO_HUGE_PAGES defined, this does nothing.
// The advice must come before the buffer is first written. It covers only
// the package's own buffers: the whole process (Eigen, CHOLMOD) gets huge
// pages from glibc with GLIBC_TUNABLES=glibc.malloc.hugetlb=1 (see the README).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Below this size a buffer is not worth advising (and may share its pages
// with other allocations).
constexpr std::size_t huge_page_advice_minimum_bytes = std::size_t(4) << 20;

// Advises huge pages for the whole 4 KB pages inside [data, data + bytes),
// a buffer that has not been written yet. The advice changes no content.
inline void advise_huge_pages(void* data, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE) && !defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_NO_HUGE_PAGES)
  if(data == nullptr || bytes < huge_page_advice_minimum_bytes) return;
  const std::uintptr_t page = 4096;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(page - 1);
  if(end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice only: errors ignored
#else
  (void)data;
  (void)bytes;
#endif
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_HUGE_PAGES_H
