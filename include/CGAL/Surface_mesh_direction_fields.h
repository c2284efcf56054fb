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

// Umbrella header of the package Surface_mesh_direction_fields.

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/feature_edges.h>
#include <CGAL/Surface_mesh_direction_fields/Globally_optimal_direction_field.h>
#include <CGAL/Surface_mesh_direction_fields/globally_optimal_directions.h>
#include <CGAL/Surface_mesh_direction_fields/globally_optimal_face_directions.h>
#include <CGAL/Surface_mesh_direction_fields/IO/direction_field_files.h>
#include <CGAL/Surface_mesh_direction_fields/openblas_thread_control.h>
#include <CGAL/Surface_mesh_direction_fields/streamlines.h>

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_H
