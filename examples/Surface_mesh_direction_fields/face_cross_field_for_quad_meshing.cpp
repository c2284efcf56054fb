// A cross field on the faces of a mesh, as quad meshers read it: one direction
// per face, singularities at vertices, the matching across each edge, and the
// .rosy and .sharp files QuadWild loads beside the mesh, and a file ParaView opens.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include <fstream>
#include <iostream>
#include <iterator>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double>                   Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>              Mesh;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/fandisk.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input file." << std::endl;
    return EXIT_FAILURE;
  }

  // the sharp edges: one direction of the cross follows them
  auto is_feature = mesh.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
  SMDF::detect_feature_edges(mesh, 35., is_feature);

  auto direction = mesh.add_property_map<Mesh::Face_index, Kernel::Vector_3>("f:direction").first;
  auto matching = mesh.add_property_map<Mesh::Edge_index, int>("e:matching", 0).first;
  std::vector<std::pair<Mesh::Vertex_index, int> > singular;  // (vertex, k): index k/4
  SMDF::Face_direction_field_result result = SMDF::compute_globally_optimal_face_directions(
    mesh, direction,
    CGAL::parameters::degree(4)
      .edge_is_feature_map(is_feature)
      .singularities_output_iterator(std::back_inserter(singular))
      .edge_matching_map(matching));
  std::cout << singular.size() << " singular vertices, index sum " << result.index_sum << "/4\n";

  // the files QuadWild reads with this mesh (written as OFF: its faces in the
  // same order), and one for ParaView: the directions per triangle, the
  // singular vertices marked
  const SMDF::Direction_field_data data = SMDF::make_face_direction_field_data(
    mesh, direction, result, singular, CGAL::parameters::edge_matching_map(matching));
  std::vector<std::array<std::size_t, 2> > features;
  for(auto e : mesh.edges())
    if(is_feature[e]) features.push_back({mesh.source(mesh.halfedge(e)), mesh.target(mesh.halfedge(e))});
  std::ofstream rosy("field.rosy"), sharp("field.sharp");
  CGAL::IO::write_OFF("field_mesh.off", mesh, CGAL::parameters::stream_precision(17));
  SMDF::IO::write_rosy(rosy, data);
  SMDF::IO::write_sharp(sharp, data, features);
  std::ofstream vtu("field.vtu");
  SMDF::IO::write_VTU(vtu, data);
  std::cout << "wrote field_mesh.off, field.rosy, field.sharp and field.vtu" << std::endl;
  return EXIT_SUCCESS;
}
