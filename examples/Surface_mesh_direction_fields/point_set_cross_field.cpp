// The smoothest cross field (n = 4) of a point set, without a mesh: here the
// vertices of a surface mesh read as points, normals estimated.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Surface_mesh_direction_fields/globally_optimal_point_set_directions.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3>                   Point_set;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

int main(int argc, char* argv[])
{
  // .xyz, .ply, .off: the points (an OFF mesh gives its vertices)
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/fandisk.off");
  Point_set points;
  if(!CGAL::IO::read_point_set(filename, points) || points.size() < 3)
  {
    std::cerr << "Invalid input file." << std::endl;
    return EXIT_FAILURE;
  }

  // One unit tangent vector per point; the cross is it and its rotations by 90 degrees.
  auto direction = points.add_property_map<Kernel::Vector_3>("direction").first;
  const SMDF::Point_set_direction_field_result result = SMDF::compute_globally_optimal_point_set_directions(
    points, direction, points.parameters().degree(4).number_of_neighbors(12));

  // The singularities sit in the triangles of the points' local triangulations.
  long index_sum = 0;
  for(const auto& s : result.singular_triangles) index_sum += s.second;
  std::cout << points.size() << " points, eigenvalue " << *result.components[0].eigenvalue << ", "
            << result.singular_triangles.size() << " singular triangles, index sum " << index_sum << "/4";
  if(result.surface_is_closed)  // then the sum is 4 times the Euler characteristic
    std::cout << " = 4 x " << result.surface_euler_characteristic;
  std::cout << "\ndirection at point 0: " << direction[*points.begin()] << std::endl;
  return EXIT_SUCCESS;
}
