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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUBNORMALS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUBNORMALS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <complex>
#include <type_traits>

#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#include <xmmintrin.h>
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_SSE_CONTROL_REGISTER 1
#endif

// Subnormal numbers in single-precision factorizations.
//
// Why: the Cholesky factor of a mesh's matrix holds many fill entries that
// decay with the distance (in the mesh) between their row and column; in
// single precision, whose smallest normal number is about 1.2e-38, the
// products that form them fall below that range, into subnormal numbers.
// x86 processors take a slow path (microcode) for every operation that reads
// or produces one: on regular surfaces of many handles or flat regions the
// factorization in single precision took several times as long as the one
// in double precision, which has no subnormal entry there (the benchmark's
// README, "Subnormal numbers"). Flushing them to zero changes each affected
// entry by less than 1.2e-38, far below single precision's relative accuracy
// of 6e-8; the single-precision factor only steers iterations whose residuals
// are computed in double precision (factored_matrix.h).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// While it lives, the calling thread treats subnormal single- and
// double-precision numbers as zero, as operands and as results (the SSE
// control register's "flush to zero" and "denormals are zero" bits), when
// `Scalar` is float or std::complex<float>; it then restores the thread's
// previous mode. It does nothing for other scalars, and nothing on
// processors without that register (the results are then the same, only
// slower where subnormal numbers occur). Each thread of a parallel loop sets
// its own mode: the guard is constructed inside the loop's body. The BLAS's
// own threads keep theirs.
template <typename Scalar>
class Subnormals_flushed_in_scope
{
  static constexpr bool single = std::is_same<Scalar, float>::value || std::is_same<Scalar, std::complex<float> >::value;
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SSE_CONTROL_REGISTER
  static constexpr unsigned int flush_to_zero = 0x8000u, denormals_are_zero = 0x0040u;
  unsigned int m_previous = 0u;

public:
  Subnormals_flushed_in_scope()
  {
    if(!single) return;
    m_previous = _mm_getcsr();
    _mm_setcsr(m_previous | flush_to_zero | denormals_are_zero);
  }
  ~Subnormals_flushed_in_scope()
  {
    if(single) _mm_setcsr(m_previous);
  }
#else
public:
  Subnormals_flushed_in_scope() {}
#endif
  // whether this guard changes the thread's mode
  static constexpr bool flushes()
  {
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SSE_CONTROL_REGISTER
    return single;
#else
    return false;
#endif
  }

  Subnormals_flushed_in_scope(const Subnormals_flushed_in_scope&) = delete;
  Subnormals_flushed_in_scope& operator=(const Subnormals_flushed_in_scope&) = delete;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SUBNORMALS_H
