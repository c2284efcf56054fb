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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_ORDERING_LOCK_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_ORDERING_LOCK_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <Eigen/Core>

#include <mutex>

// One ordering by METIS at a time in the process.
//
// CHOLMOD's analysis may call METIS to order a matrix (always where the
// package asks for it, on large matrices; in CHOLMOD's default strategy
// where AMD's fill is high), and METIS draws its random numbers from the C
// library's one generator, seeding it anew at each call. Two orderings at
// once interleave their draws: each gets an ordering that depends on the
// threads' timing, and so do the last digits of the fields factored on it
// (measured on a 600,000-row grid: both orderings differed from the one of a
// run alone). Every analysis of the package that may call METIS holds this
// lock for its length; one that orders by AMD alone, as the small matrices
// of the coarse estimate do while a large matrix is ordered beside them,
// does not need it.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

inline std::mutex& metis_ordering_lock()
{
  static std::mutex lock;
  return lock;
}

// Below this many rows the package's analyses order by AMD alone, without
// METIS (CHOLMOD's default strategy would not try METIS on these matrices:
// their factors are too small for its fill test), so they take no lock.
constexpr Eigen::Index amd_only_size = 5000;

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_ORDERING_LOCK_H
