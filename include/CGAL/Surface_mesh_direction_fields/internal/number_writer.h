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

// Text files of numbers written fast (the exchange files, the program's
// outputs): std::to_chars into a buffer gives the same text as an ostream
// with std::setprecision(17) ("%.17g": reading it back gives the same
// double), several times faster than the stream's own formatting.
#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_NUMBER_WRITER_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_NUMBER_WRITER_H

#include <charconv>
#include <ostream>
#include <string>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

class Number_writer
{
public:
  explicit Number_writer(std::ostream& os) : os_(os) { buffer_.reserve(capacity + 64); }
  ~Number_writer() { flush(); }

  Number_writer& number(double x)
  {
    char text[32];
    const char* end = std::to_chars(text, text + sizeof text, x, std::chars_format::general, 17).ptr;
    return append(text, end);
  }
  Number_writer& integer(long long i)
  {
    char text[24];
    return append(text, std::to_chars(text, text + sizeof text, i).ptr);
  }
  Number_writer& text(const std::string& s) { return append(s.data(), s.data() + s.size()); }
  Number_writer& text(const char* s) { return append(s, s + std::char_traits<char>::length(s)); }
  Number_writer& space() { return append(" ", " " + 1); }
  Number_writer& end_line() { return append("\n", "\n" + 1); }

  // "x y z\n"
  void line(double x, double y, double z) { number(x).space().number(y).space().number(z).end_line(); }

  void flush()
  {
    os_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

private:
  static constexpr std::size_t capacity = 1 << 16;
  Number_writer& append(const char* first, const char* last)
  {
    buffer_.append(first, last);
    if(buffer_.size() >= capacity) flush();
    return *this;
  }
  std::ostream& os_;
  std::string buffer_;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif
