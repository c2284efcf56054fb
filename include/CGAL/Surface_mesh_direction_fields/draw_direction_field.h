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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_DRAW_DIRECTION_FIELD_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_DRAW_DIRECTION_FIELD_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>
#include <CGAL/Surface_mesh_direction_fields/streamlines.h>

#ifdef DOXYGEN_RUNNING

namespace CGAL {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

opens a window (CGAL's basic viewer) showing `tmesh`, its direction field and
its singularities, following the convention of CGAL's `draw()` functions: the
call blocks until the window is closed. Each vertex shows its `n` directions
as short segments (0.4 times the mean edge length); singular faces are red
(positive index) or blue (negative index), the others grey.

Available when the macro `CGAL_USE_BASIC_VIEWER` is defined: link with the CMake
target `CGAL::CGAL_Basic_viewer` (Debian's `libcgal-qt5-dev`). When the
environment variable `CGAL_TEST_SUITE` is set, nothing is shown.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam VertexDirectionMap a `ReadablePropertyMap` from vertices to a 3D vector type
\tparam SingularityRange a range of `std::pair<face_descriptor, int>`

\param tmesh the mesh
\param direction_map the first direction of each vertex (as written by `compute_globally_optimal_directions()`)
\param singularities the singular faces with their integers `k`
\param np named parameters: `degree` (default 1), and those of `make_direction_field_data()`
*/
template <typename TriangleMesh, typename VertexDirectionMap, typename SingularityRange, typename NamedParameters>
void draw(const TriangleMesh& tmesh, VertexDirectionMap direction_map, const SingularityRange& singularities,
          const NamedParameters& np);

namespace Surface_mesh_direction_fields {
/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

the same scene from plain data, with field lines (`trace_streamlines()`) drawn
in dark blue-green.

\param data the field with its mesh
\param streamlines the lines to draw (may be empty)
\param title the title of the window
*/
void draw_direction_field(const Direction_field_data& data, const std::vector<Streamline>& streamlines,
                          const char* title = "Direction field");
} // namespace Surface_mesh_direction_fields

} // namespace CGAL

#else // DOXYGEN_RUNNING

#ifdef CGAL_USE_BASIC_VIEWER

#include <CGAL/Qt/Basic_viewer_qt.h>
#include <CGAL/Qt/init_ogl_context.h>

#include <QKeyEvent>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

class Direction_field_viewer : public CGAL::Basic_viewer_qt
{
  typedef CGAL::Basic_viewer_qt Base;
  const Direction_field_data& m_data;
  const std::vector<Streamline>& m_lines;

public:
  Direction_field_viewer(QWidget* parent, const Direction_field_data& data,
                         const std::vector<Streamline>& lines, const char* title)
    : Base(parent, title, false, true, true, false, false), m_data(data), m_lines(lines)
  {
    compute_elements();
  }

protected:
  // Escape closes the window too (CGAL's viewer closes on Ctrl+Q only).
  void keyPressEvent(QKeyEvent* e) override
  {
    if(e->key() == ::Qt::Key_Escape && e->modifiers() == ::Qt::NoModifier)
    {
      close();
      return;
    }
    Base::keyPressEvent(e);
  }

private:
  static Local_point point(const std::array<double, 3>& p) { return Local_point(p[0], p[1], p[2]); }

  void compute_elements()
  {
    clear();
    std::vector<int> index(m_data.faces.size(), 0);
    for(const auto& s : m_data.singularities) index[s.first] = s.second;
    double edge_sum = 0.;
    for(std::size_t f = 0; f < m_data.faces.size(); ++f)
    {
      const auto& t = m_data.faces[f];
      const CGAL::IO::Color color = index[f] > 0 ? CGAL::IO::Color(230, 40, 40)
                                  : index[f] < 0 ? CGAL::IO::Color(40, 80, 230) : CGAL::IO::Color(200, 205, 215);
      face_begin(color);
      for(std::size_t v : t) add_point_in_face(point(m_data.points[v]));
      face_end();
      for(int c = 0; c < 3; ++c)
      {
        edge_sum += internal::norm(m_data.points[t[(c + 1) % 3]] - m_data.points[t[c]]);
      }
    }
    const double glyph = m_data.faces.empty() ? 0. : 0.4 * edge_sum / (3. * m_data.faces.size());
    const bool signed_directions = m_data.degree % 2 == 1;  // odd n: arrowheads show which way
    for(std::size_t v = 0; v < m_data.directions.size(); ++v)
      for(const auto& d : m_data.directions[v])
      {
        if(internal::dot(d, d) == 0.) continue;
        const internal::Vec3& p = m_data.points[v];
        const internal::Vec3 tip = p + glyph * d;
        add_segment(point(p), point(tip), CGAL::IO::Color(20, 20, 20));
        if(signed_directions && v < m_data.normals.size())
          add_arrowhead(tip, d, m_data.normals[v], 0.3 * glyph, CGAL::IO::Color(20, 20, 20));
      }
    for(const Streamline& l : m_lines)
      for(std::size_t i = 0; i + 1 < l.points.size(); ++i)
      {
        add_segment(point(l.points[i]), point(l.points[i + 1]), CGAL::IO::Color(20, 90, 100));
        if(signed_directions && i % 8 == 4 && i < l.faces.size())  // every few faces along the line
        {
          const internal::Vec3 e = l.points[i + 1] - l.points[i];
          const auto& t = m_data.faces[l.faces[i]];
          const internal::Vec3 normal =
            internal::cross(m_data.points[t[1]] - m_data.points[t[0]], m_data.points[t[2]] - m_data.points[t[0]]);
          if(internal::norm(e) > 0. && internal::norm(normal) > 0.)
            add_arrowhead(l.points[i + 1], internal::normalized(e), internal::normalized(normal), 1.2 * glyph,
                          CGAL::IO::Color(20, 90, 100));
        }
      }
  }

  // Two short strokes back from `tip`, on either side of the unit direction
  // d in the plane of the unit normal.
  void add_arrowhead(const internal::Vec3& tip, const internal::Vec3& d, const internal::Vec3& normal, double size,
                     const CGAL::IO::Color& color)
  {
    const internal::Vec3 side = internal::cross(normal, d);
    add_segment(point(tip), point(tip + (-size) * d + (0.6 * size) * side), color);
    add_segment(point(tip), point(tip + (-size) * d + (-0.6 * size) * side), color);
  }
};

} // namespace internal

inline void draw_direction_field(const Direction_field_data& data, const std::vector<Streamline>& streamlines,
                                 const char* title = "Direction field")
{
#if defined(CGAL_TEST_SUITE)
  const bool cgal_test_suite = true;
#else
  const bool cgal_test_suite = qEnvironmentVariableIsSet("CGAL_TEST_SUITE");
#endif
  if(cgal_test_suite) return;
  CGAL::Qt::init_ogl_context(4, 3);
  int argc = 1;
  const char* argv[2] = {"direction_field_viewer", nullptr};
  QApplication app(argc, const_cast<char**>(argv));
  internal::Direction_field_viewer window(app.activeWindow(), data, streamlines, title);
  window.show();
  app.exec();
}

} // namespace Surface_mesh_direction_fields

inline void draw(const Surface_mesh_direction_fields::Direction_field_data& data)
{
  Surface_mesh_direction_fields::draw_direction_field(data, std::vector<Surface_mesh_direction_fields::Streamline>(),
                                                      "Direction field");
}

template <typename TriangleMesh, typename VertexDirectionMap, typename SingularityRange,
          typename NamedParameters = parameters::Default_named_parameters>
void draw(const TriangleMesh& tmesh, VertexDirectionMap direction_map, const SingularityRange& singularities,
          const NamedParameters& np = parameters::default_values())
{
  const int degree = parameters::choose_parameter(parameters::get_parameter(np, internal_np::degree), 1);
  const Surface_mesh_direction_fields::Direction_field_data data =
    Surface_mesh_direction_fields::make_direction_field_data(tmesh, direction_map, degree, singularities, np);
  draw(data);
}

} // namespace CGAL

#endif // CGAL_USE_BASIC_VIEWER

#endif // DOXYGEN_RUNNING

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_DRAW_DIRECTION_FIELD_H
