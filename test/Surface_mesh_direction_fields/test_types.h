// The types the tests share: a Surface_mesh over doubles, its indices, and
// the short name of CGAL's named parameters. Each test names the package's
// namespace itself (`SMDF`): some give that name to the internal namespace.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_TEST_TYPES_H
#define SURFACE_MESH_DIRECTION_FIELDS_TEST_TYPES_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Edge_index Edge_index;
namespace params = CGAL::parameters;

#endif
