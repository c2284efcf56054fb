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
//
// Out-of-tree stand-in for the file CGAL generates from
// Installation/include/CGAL/license/gpl_package_list.txt. When the package is
// merged into CGAL, this file is deleted and the line
// "Surface_mesh_direction_fields Surface Mesh Direction Fields" is added there.

#ifndef CGAL_LICENSE_SURFACE_MESH_DIRECTION_FIELDS_H
#define CGAL_LICENSE_SURFACE_MESH_DIRECTION_FIELDS_H

#include <CGAL/config.h>
#include <CGAL/license.h>

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_COMMERCIAL_LICENSE

#  if CGAL_SURFACE_MESH_DIRECTION_FIELDS_COMMERCIAL_LICENSE < CGAL_RELEASE_DATE
#    if defined(CGAL_LICENSE_WARNING)
       CGAL_pragma_warning("Your commercial license for CGAL does not cover "
                           "this release of the Surface Mesh Direction Fields package.")
#    endif
#    ifdef CGAL_LICENSE_ERROR
#      error "Your commercial license for CGAL does not cover this release \
of the Surface Mesh Direction Fields package. \
You get this error, as you defined CGAL_LICENSE_ERROR."
#    endif // CGAL_LICENSE_ERROR
#  endif

#else // no CGAL_SURFACE_MESH_DIRECTION_FIELDS_COMMERCIAL_LICENSE

#  if defined(CGAL_LICENSE_WARNING)
     CGAL_pragma_warning("\nThe macro CGAL_SURFACE_MESH_DIRECTION_FIELDS_COMMERCIAL_LICENSE is not defined."
                          "\nYou use the CGAL Surface Mesh Direction Fields package under "
                          "the terms of the GPLv3+.")
#  endif // CGAL_LICENSE_WARNING
#  ifdef CGAL_LICENSE_ERROR
#    error "The macro CGAL_SURFACE_MESH_DIRECTION_FIELDS_COMMERCIAL_LICENSE is not defined.\
 You use the CGAL Surface Mesh Direction Fields package under the terms of \
the GPLv3+. You get this error, as you defined CGAL_LICENSE_ERROR."
#  endif // CGAL_LICENSE_ERROR

#endif // no CGAL_SURFACE_MESH_DIRECTION_FIELDS_COMMERCIAL_LICENSE

#endif // CGAL_LICENSE_SURFACE_MESH_DIRECTION_FIELDS_H
