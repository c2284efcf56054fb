// A cross field (n = 4) that follows the principal curvature directions of a
// CAD model, with a chosen trade-off between alignment and smoothness.
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
  auto direction = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:direction").first;
  std::vector<std::pair<Mesh::Face_index, int> > singularities;

  // t close to 1 follows the curvature, close to 0 is smooth; flat and umbilic
  // regions, where the curvature says nothing, are filled in smoothly anyway.
  for(double t : {0.5, 0.9, 0.99})
  {
    singularities.clear();
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      mesh, direction,
      CGAL::parameters::degree(4)
        .principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM)
        .alignment_weight(t)
        .singularities_output_iterator(std::back_inserter(singularities)));
    std::cout << "t = " << r.components[0].alignment_weight << ": lambda_t = " << r.components[0].lambda
              << " (below lambda_1 = " << *r.components[0].eigenvalue << "), " << singularities.size()
              << " singular faces, index sum " << r.index_sum << "/4\n";
  }
  return EXIT_SUCCESS;
}
