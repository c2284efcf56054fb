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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_SINGULARITY_LIST_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_SINGULARITY_LIST_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/number_writer.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>
#include <CGAL/Surface_mesh_direction_fields/IO/internal/file_tokens.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// The singular faces with their indices and barycentres, one per line.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace IO {

/// \name Singularities
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the singularities as text: a comment line, then one line per singular
face: `face k n x y z` (its index is `k / n`; `x y z` is its barycentre).

\param os the output stream
\param data the field to write
*/
inline void write_singularities(std::ostream& os, const Direction_field_data& data)
{
  os << std::setprecision(17);
  os << "# face k n x y z   (index k/n at the barycentre x y z)\n";
  for(std::size_t i = 0; i < data.singularities.size(); ++i)
  {
    const auto& p = data.singularity_points[i];
    os << data.singularities[i].first << " " << data.singularities[i].second << " " << data.degree << " " << p[0]
       << " " << p[1] << " " << p[2] << "\n";
  }
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a file written by `write_singularities()`: sets `singularities`,
`singularity_points` and `degree` of `data`.

\throws Invalid_input_error on a malformed line
\param is the input stream
\param data receives what the file holds
*/
inline void read_singularities(std::istream& is, Direction_field_data& data)
{
  data.singularities.clear();
  data.singularity_points.clear();
  std::string line;
  std::size_t number = 0;
  while(std::getline(is, line))
  {
    ++number;
    if(line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::size_t f;
    int k, n;
    std::array<double, 3> p;
    if(!(ls >> f >> k >> n >> p[0] >> p[1] >> p[2]))
      throw Invalid_input_error("singularities file: line " + std::to_string(number) + " is malformed");
    data.degree = n;
    data.singularities.emplace_back(f, k);
    data.singularity_points.push_back(p);
  }
}

/// @}

} // namespace IO
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_SINGULARITY_LIST_H
