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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_OPENBLAS_THREAD_CONTROL_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_OPENBLAS_THREAD_CONTROL_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/dense_kernels.h>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Lets the package's factorization (the default solver,
`Cholmod_supernodal_solver`) set OpenBLAS's number of threads to one while
its own threads factor the small supernodes side by side, and give the
previous number back afterwards. This setting is process-wide: another
thread of the program that calls OpenBLAS meanwhile runs on one thread. It
makes a whole computation about 4 to 11% faster.

Off by default: then the package changes nothing outside its own memory and
threads (those supernodes are factored with kernels written with Eigen). It
has an effect only where the package is linked with OpenBLAS; the
`direction_field` program switches it on. The fields are exact either way;
their last digits depend on the setting.

\param enabled whether the package may set OpenBLAS's number of threads
*/
inline void set_openblas_thread_control(bool enabled)
{
  internal::openblas_thread_control_requested().store(enabled);
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Tells whether the package sets OpenBLAS's number of threads during its
factorizations.

\return `true` if `set_openblas_thread_control(true)` was called last and
OpenBLAS's thread control is linked
*/
inline bool openblas_thread_control()
{
  return internal::controls_blas_threads();
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_OPENBLAS_THREAD_CONTROL_H
