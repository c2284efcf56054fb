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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_ALIGNMENT_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_ALIGNMENT_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Which principal curvature direction guides the field (named parameter
`principal_curvature_alignment`). The guidance is the discrete Hopf
differential: a line field along the maximum curvature direction, weighted by
the difference of the principal curvatures (it vanishes at umbilics). For a
degree `n`, its `n/2`-th power is used, so `n` must be even; for `n = 4` the two
values give the same cross (both directions at once).
*/
enum class Principal_curvature_alignment
{
  NONE,     ///< no curvature guidance
  MAXIMUM,  ///< along the direction of maximum curvature
  MINIMUM   ///< along the direction of minimum curvature
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Hard constraints at the boundary vertices (named parameter `boundary_alignment`).
*/
enum class Boundary_alignment
{
  NONE,     ///< no constraint on the boundary
  TANGENT,  ///< one of the `n` directions is tangent to the boundary
  NORMAL    ///< one of the `n` directions is normal to the boundary
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_ALIGNMENT_H
