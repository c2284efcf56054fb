// Shows the smoothest cross field of a mesh in CGAL's basic viewer: the four
// directions at each vertex, the singular faces (red: +, blue: -), then a
// second window with the field lines, a third with the field on faces.
//   usage: view_direction_field [MESH] [n]
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/draw_direction_field.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/fandisk.off");
  const int degree = argc > 2 ? std::atoi(argv[2]) : 4;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << path << std::endl;
    return EXIT_FAILURE;
  }
  auto direction = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:direction").first;
  std::vector<std::pair<Mesh::Face_index, int> > singularities;
  const SMDF::Direction_field_result result = SMDF::compute_globally_optimal_directions(
    mesh, direction, CGAL::parameters::degree(degree).singularities_output_iterator(std::back_inserter(singularities)));

  // the plain data carries n (from the result): nothing asks for it again
  const SMDF::Direction_field_data data = SMDF::make_direction_field_data(mesh, direction, result, singularities);
  CGAL::draw(data);
  const std::vector<SMDF::Streamline> lines = SMDF::trace_streamlines(data);
  std::cout << singularities.size() << " singular faces, " << lines.size() << " field lines" << std::endl;
  SMDF::draw_direction_field(data, lines, "Field lines");

  // the field on faces, as quad meshers read it: directions at the triangles'
  // centres, singularities at vertices
  auto face_direction = mesh.add_property_map<Mesh::Face_index, Kernel::Vector_3>("f:direction").first;
  std::vector<std::pair<Mesh::Vertex_index, int> > singular_vertices;
  const SMDF::Face_direction_field_result on_faces = SMDF::compute_globally_optimal_face_directions(
    mesh, face_direction,
    CGAL::parameters::degree(degree).singularities_output_iterator(std::back_inserter(singular_vertices)));
  SMDF::draw_direction_field(SMDF::make_face_direction_field_data(mesh, face_direction, on_faces, singular_vertices),
                             std::vector<SMDF::Streamline>(), "Field on faces");
  return lines.empty() ? EXIT_FAILURE : EXIT_SUCCESS;
}
