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
`principal_curvature_alignment`). The guidance is a line field along the
maximum curvature direction, weighted by the difference of the principal
curvatures (it vanishes at umbilics), estimated as
`principal_curvature_estimate` says. For a degree `n`, its `n/2`-th power is
used, so `n` must be even; for `n = 4` the two values give the same cross
(both directions at once).
*/
enum class Principal_curvature_alignment
{
  NONE,     ///< no curvature guidance
  MAXIMUM,  ///< along the direction of maximum curvature
  MINIMUM   ///< along the direction of minimum curvature
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

How the principal curvature directions are estimated (named parameter
`principal_curvature_estimate`), see the user manual, section "Aligned and
Constrained Fields".
*/
enum class Principal_curvature_estimate
{
  /// at each vertex, a least-squares quadric fitted to its two-ring: close to
  /// the surface's own directions on irregular triangulations (the default)
  QUADRIC_FIT,
  /// the discrete Hopf differential of the paper, from the dihedral angles of
  /// the edges, projected onto the vertices with the mass matrix: exact in the
  /// integral sense, but noisy at each vertex of an irregular triangulation
  HOPF_DIFFERENTIAL
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
