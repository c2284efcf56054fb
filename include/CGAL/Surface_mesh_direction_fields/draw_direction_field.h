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
target `CGAL::CGAL_Basic_viewer` (with CGAL 5.5, Qt5: Debian's `libcgal-qt5-dev`;
with CGAL 6, Qt6: Debian's `qt6-base-dev`). When the environment variable
`CGAL_TEST_SUITE` is set, nothing is shown.

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
in dark blue-green. A field on faces (`make_face_direction_field_data()`)
shows its `n` directions at each triangle's centre and its singular vertices
as points, red or blue by the sign of their index.

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

#include <CGAL/Surface_mesh_direction_fields/internal/cgal_compatibility.h>

#if CGAL_SURFACE_MESH_DIRECTION_FIELDS_CGAL_6
// CGAL 6.0 guards its Qt viewer by CGAL_USE_BASIC_VIEWER, 6.1 by CGAL_USE_BASIC_VIEWER_QT
#ifndef CGAL_USE_BASIC_VIEWER_QT
#define CGAL_USE_BASIC_VIEWER_QT 1
#endif
#include <CGAL/Graphics_scene.h>
#include <CGAL/Qt/Basic_viewer.h>
#else
#include <CGAL/Qt/Basic_viewer_qt.h>
#endif
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Qt/init_ogl_context.h>

#include <QApplication>
#include <QKeyEvent>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// What the viewer shows, added to `scene`: CGAL 5's viewer itself or CGAL 6's
// Graphics_scene (the same face_begin / add_point_in_face / face_end /
// add_segment calls in both).
template <typename Scene>
class Direction_field_scene_builder
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;
  Scene& m_scene;

  static Point point(const std::array<double, 3>& p) { return Point(p[0], p[1], p[2]); }

public:
  explicit Direction_field_scene_builder(Scene& scene) : m_scene(scene) {}

  void add(const Direction_field_data& data, const std::vector<Streamline>& lines)
  {
    const double glyph = add_faces(data);
    const bool signed_directions = data.degree % 2 == 1;  // odd n: arrowheads show which way
    for(std::size_t v = 0; v < data.directions.size(); ++v)
      for(const auto& d : data.directions[v])
      {
        if(internal::dot(d, d) == 0.) continue;
        const internal::Vec3& p = data.points[v];
        const internal::Vec3 tip = p + glyph * d;
        m_scene.add_segment(point(p), point(tip), CGAL::IO::Color(20, 20, 20));
        if(signed_directions && v < data.normals.size())
          add_arrowhead(tip, d, data.normals[v], 0.3 * glyph, CGAL::IO::Color(20, 20, 20));
      }
    if(holds_field_on_faces(data)) add_face_field(data, signed_directions, glyph);
    for(const Streamline& l : lines) add_line(data, l, signed_directions, glyph);
  }

private:
  // A field on faces: the n directions at each triangle's centre, the
  // singular vertices as points in their index's colour.
  void add_face_field(const Direction_field_data& data, bool signed_directions, double glyph)
  {
    for(std::size_t f = 0; f < data.faces.size(); ++f)
    {
      const internal::Vec3 normal = internal::triangle_unit_normal(data.points, data.faces[f]);
      const internal::Vec3 centre = internal::barycentre(data.points, data.faces[f]);
      for(int k = 0; k < data.degree; ++k)
      {
        const internal::Vec3 d = internal::rotated(data.face_directions[f], normal, 2. * CGAL_PI * k / data.degree);
        if(internal::dot(d, d) == 0.) continue;
        const internal::Vec3 tip = centre + glyph * d;
        m_scene.add_segment(point(centre), point(tip), CGAL::IO::Color(20, 20, 20));
        if(signed_directions) add_arrowhead(tip, d, normal, 0.3 * glyph, CGAL::IO::Color(20, 20, 20));
      }
    }
    for(const auto& vk : data.vertex_singularities)
      m_scene.add_point(point(data.points[vk.first]), vk.second > 0 ? CGAL::IO::Color(230, 40, 40)
                                                                    : CGAL::IO::Color(40, 80, 230));
  }

  // The faces, coloured by their index; returns the glyphs' length.
  double add_faces(const Direction_field_data& data)
  {
    std::vector<int> index(data.faces.size(), 0);
    for(const auto& s : data.singularities) index[s.first] = s.second;
    double edge_sum = 0.;
    for(std::size_t f = 0; f < data.faces.size(); ++f)
    {
      const auto& t = data.faces[f];
      const CGAL::IO::Color color = index[f] > 0 ? CGAL::IO::Color(230, 40, 40)
                                  : index[f] < 0 ? CGAL::IO::Color(40, 80, 230) : CGAL::IO::Color(200, 205, 215);
      m_scene.face_begin(color);
      for(std::size_t v : t) m_scene.add_point_in_face(point(data.points[v]));
      m_scene.face_end();
      for(int c = 0; c < 3; ++c) edge_sum += internal::norm(data.points[t[(c + 1) % 3]] - data.points[t[c]]);
    }
    return data.faces.empty() ? 0. : 0.4 * edge_sum / (3. * data.faces.size());
  }

  void add_line(const Direction_field_data& data, const Streamline& l, bool signed_directions, double glyph)
  {
    const CGAL::IO::Color color(20, 90, 100);
    for(std::size_t i = 0; i + 1 < l.points.size(); ++i)
    {
      m_scene.add_segment(point(l.points[i]), point(l.points[i + 1]), color);
      if(!signed_directions || i % 8 != 4 || i >= l.faces.size()) continue;  // every few faces along the line
      const internal::Vec3 e = l.points[i + 1] - l.points[i];
      const auto& t = data.faces[l.faces[i]];
      const internal::Vec3 normal = internal::triangle_unit_normal(data.points, t);
      if(internal::norm(e) > 0. && internal::norm(normal) > 0.)
        add_arrowhead(l.points[i + 1], internal::normalized(e), normal, 1.2 * glyph, color);
    }
  }

  // Two short strokes back from `tip`, on either side of the unit direction
  // d in the plane of the unit normal.
  void add_arrowhead(const internal::Vec3& tip, const internal::Vec3& d, const internal::Vec3& normal, double size,
                     const CGAL::IO::Color& color)
  {
    const internal::Vec3 side = internal::cross(normal, d);
    m_scene.add_segment(point(tip), point(tip + (-size) * d + (0.6 * size) * side), color);
    m_scene.add_segment(point(tip), point(tip + (-size) * d + (-0.6 * size) * side), color);
  }
};

#if CGAL_SURFACE_MESH_DIRECTION_FIELDS_CGAL_6

// CGAL 6: the viewer shows a Graphics_scene it keeps by reference, so the
// scene is a base constructed (and filled) before the viewer.
struct Direction_field_scene
{
  CGAL::Graphics_scene scene;
  Direction_field_scene(const Direction_field_data& data, const std::vector<Streamline>& lines)
  {
    Direction_field_scene_builder<CGAL::Graphics_scene>(scene).add(data, lines);
  }
};

class Direction_field_viewer : private Direction_field_scene, public CGAL::Qt::Basic_viewer
{
  typedef CGAL::Qt::Basic_viewer Base;

public:
  Direction_field_viewer(QWidget* parent, const Direction_field_data& data, const std::vector<Streamline>& lines,
                         const char* title)
    : Direction_field_scene(data, lines), Base(parent, scene, title, false, true, true, false, false)
  {}

#else

// CGAL 5: the viewer is its own scene.
class Direction_field_viewer : public CGAL::Basic_viewer_qt
{
  typedef CGAL::Basic_viewer_qt Base;

public:
  Direction_field_viewer(QWidget* parent, const Direction_field_data& data, const std::vector<Streamline>& lines,
                         const char* title)
    : Base(parent, title, false, true, true, false, false)
  {
    Direction_field_scene_builder<Base>(*this).add(data, lines);
  }

#endif

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
  const int degree = parameters::choose_parameter(parameters::get_parameter(np, internal_np::degree),
                                                  Surface_mesh_direction_fields::default_degree);
  const Surface_mesh_direction_fields::Direction_field_data data =
    Surface_mesh_direction_fields::make_direction_field_data(tmesh, direction_map, degree, singularities, np);
  draw(data);
}

} // namespace CGAL

#endif // CGAL_USE_BASIC_VIEWER

#endif // DOXYGEN_RUNNING

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_DRAW_DIRECTION_FIELD_H
