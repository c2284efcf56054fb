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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_DIRECTION_FIELD_FILES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_DIRECTION_FIELD_FILES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

// Every writer and reader of direction fields, one header per format.
#include <CGAL/Surface_mesh_direction_fields/IO/PLY.h>
#include <CGAL/Surface_mesh_direction_fields/IO/VTK.h>
#include <CGAL/Surface_mesh_direction_fields/IO/face_field_files.h>
#include <CGAL/Surface_mesh_direction_fields/IO/field_lines.h>
#include <CGAL/Surface_mesh_direction_fields/IO/quad_mesher_files.h>
#include <CGAL/Surface_mesh_direction_fields/IO/singularity_list.h>

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_DIRECTION_FIELD_FILES_H
