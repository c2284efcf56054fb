// A cross field on a Polyhedron_3: any FaceListGraph works; its outputs go to
// property maps the user chooses (here a dynamic vertex property).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include <iostream>
#include <iterator>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel     Kernel;
typedef CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3> Polyhedron;
typedef boost::graph_traits<Polyhedron>::vertex_descriptor      Vertex;
typedef boost::graph_traits<Polyhedron>::face_descriptor        Face;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/fandisk.off");
  Polyhedron mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input file." << std::endl;
    return EXIT_FAILURE;
  }
  // The items carry ids; numbered once, they serve as the package's vertex and
  // face indices (without ids the package numbers the elements itself).
  CGAL::set_halfedgeds_items_id(mesh);

  // A polyhedron has no property of its own for a direction: a dynamic map holds it.
  auto direction = get(CGAL::dynamic_vertex_property_t<Kernel::Vector_3>(), mesh);
  std::vector<std::pair<Face, int> > singularities;  // (face, k): index k/4

  const SMDF::Direction_field_result result = SMDF::compute_globally_optimal_directions(
    mesh, direction, CGAL::parameters::degree(4).singularities_output_iterator(std::back_inserter(singularities)));

  std::cout << num_vertices(mesh) << " vertices, " << singularities.size() << " singular faces, index sum "
            << result.index_sum << "/4 (4 times the Euler characteristic on a closed mesh)\n";
  const Vertex first = *vertices(mesh).begin();
  std::cout << "direction at the first vertex: " << get(direction, first) << std::endl;
  return EXIT_SUCCESS;
}
