// Two ways of telling the field where to go:
//  * a few strokes: guidance vectors on a handful of vertices (zero elsewhere);
//  * hard constraints: a field on a disk whose directions are tangent to its boundary.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include <cmath>
#include <iostream>

typedef CGAL::Simple_cartesian<double>                   Kernel;
typedef Kernel::Point_3                                  Point_3;
typedef Kernel::Vector_3                                 Vector_3;
typedef CGAL::Surface_mesh<Point_3>                      Mesh;
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

  // A stroke: the vertices near a plane get the guidance "along x"; the length
  // of a guidance vector is its weight, the zero vector means "no opinion".
  auto guidance = mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:guidance", CGAL::NULL_VECTOR).first;
  std::size_t stroke = 0;
  for(Mesh::Vertex_index v : mesh.vertices())
    if(std::abs(mesh.point(v).y()) < 0.02) { guidance[v] = Vector_3(1, 0, 0); ++stroke; }

  auto direction = mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:direction").first;
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
    mesh, direction, CGAL::parameters::degree(4).vertex_guidance_map(guidance).alignment_weight(0.5));
  std::cout << "stroke of " << stroke << " vertices: alignment weight " << r.components[0].alignment_weight
            << ", " << r.number_of_singular_faces << " singular faces\n";

  // A disk (made here: a fan of rings) with a cross field tangent to its boundary.
  Mesh disk;
  const int rings = 12, sectors = 48;
  std::vector<std::vector<Mesh::Vertex_index> > ring(rings + 1);
  ring[0].push_back(disk.add_vertex(Point_3(0, 0, 0)));
  for(int k = 1; k <= rings; ++k)
    for(int j = 0; j < sectors; ++j)
    {
      const double a = 2. * CGAL_PI * (j + 0.5 * k) / sectors, radius = double(k) / rings;
      ring[k].push_back(disk.add_vertex(Point_3(radius * std::cos(a), radius * std::sin(a), 0)));
    }
  for(int j = 0; j < sectors; ++j) disk.add_face(ring[0][0], ring[1][j], ring[1][(j + 1) % sectors]);
  for(int k = 1; k < rings; ++k)
    for(int j = 0; j < sectors; ++j)
    {
      disk.add_face(ring[k][j], ring[k + 1][j], ring[k + 1][(j + 1) % sectors]);
      disk.add_face(ring[k][j], ring[k + 1][(j + 1) % sectors], ring[k][(j + 1) % sectors]);
    }
  auto disk_direction = disk.add_property_map<Mesh::Vertex_index, Vector_3>("v:direction").first;
  const SMDF::Direction_field_result d = SMDF::compute_globally_optimal_directions(
    disk, disk_direction,
    CGAL::parameters::degree(4).boundary_alignment(SMDF::Boundary_alignment::TANGENT));
  // a disk has chi = 1: the crosses turn by 4 quarter turns inside
  std::cout << "boundary-aligned cross field on a disk: " << d.number_of_singular_faces
            << " singular faces, index sum " << d.index_sum << "/4\n";
  return EXIT_SUCCESS;
}
