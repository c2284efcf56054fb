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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_INTERNAL_FILE_TOKENS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_INTERNAL_FILE_TOKENS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/number_writer.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

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

// Tokens and numbers of the text formats, read with the file kind in every error.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Reads the next token, or throws with the file kind in the message.
inline std::string next_token(std::istream& is, const char* kind)
{
  std::string t;
  if(!(is >> t)) throw Invalid_input_error(std::string("truncated ") + kind + " file");
  return t;
}

// A number from a whole string, or Invalid_input_error.
template <typename T>
T parse_value(const std::string& t, const char* kind)
{
  std::istringstream ts(t);
  T value;
  if(!(ts >> value) || !ts.eof())
    throw Invalid_input_error(std::string("unexpected '") + t + "' in " + kind + " file");
  return value;
}

template <typename T>
T next_value(std::istream& is, const char* kind)
{
  const std::string t = next_token(is, kind);
  std::istringstream ts(t);
  T value;
  if(!(ts >> value) || !ts.eof())
    throw Invalid_input_error(std::string("unexpected '") + t + "' in " + kind + " file");
  return value;
}

inline void expect(std::istream& is, const std::string& word, const char* kind)
{
  const std::string t = next_token(is, kind);
  if(t != word)
    throw Invalid_input_error(std::string(kind) + " file: expected '" + word + "', found '" + t + "'");
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_INTERNAL_FILE_TOKENS_H
