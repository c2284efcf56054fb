// The smoothest cross field (n = 4) of a surface mesh and its singularities.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

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

  // One unit tangent vector per vertex; the cross is it and its rotations by 90 degrees.
  auto direction = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:direction").first;
  std::vector<std::pair<Mesh::Face_index, int> > singularities;  // (face, k): index k/4

  SMDF::Direction_field_result result = SMDF::compute_globally_optimal_directions(
    mesh, direction,
    CGAL::parameters::degree(4).singularities_output_iterator(std::back_inserter(singularities)));

  std::cout << "eigenvalue " << *result.components[0].eigenvalue << ", "
            << singularities.size() << " singular faces, index sum " << result.index_sum << "/4\n";
  for(const auto& s : singularities)
    std::cout << "  face " << s.first << ": index " << s.second << "/4\n";
  std::cout << "direction at vertex 0: " << direction[Mesh::Vertex_index(0)] << std::endl;
  return EXIT_SUCCESS;
}
