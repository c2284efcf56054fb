// Placing singularities: the smoothest cross field (n = 4) of a CAD model
// chooses its singularities; they are then edited (one moved to a
// neighbouring face, a +1/4 and -1/4 pair added) and given back as
// prescribed_singularities. The class keeps its factorization, so each edit
// costs one sparse solve.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include <algorithm>
#include <iostream>
#include <iterator>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double>                   Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>              Mesh;
typedef Mesh::Face_index                                 Face_index;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

// A face next to f that holds no singularity yet.
Face_index free_neighbour(const Mesh& mesh, Face_index f, const std::vector<std::pair<Face_index, int> >& taken)
{
  for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
  {
    const Face_index g = mesh.face(mesh.opposite(h));
    if(g != Mesh::null_face() &&
       std::none_of(taken.begin(), taken.end(), [g](const std::pair<Face_index, int>& s) { return s.first == g; }))
      return g;
  }
  return f;
}

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
  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);

  // 1. the smoothest field places its singularities
  std::vector<std::pair<Face_index, int> > singularities;
  field.compute(direction, CGAL::parameters::degree(4).singularities_output_iterator(std::back_inserter(singularities)));
  std::cout << "smoothest field: " << singularities.size() << " singular faces" << std::endl;

  // 2. edits: move the first singularity, add a +1/4 -1/4 pair (the sum stays n chi = 8)
  std::vector<std::pair<Face_index, int> > edited = singularities;
  edited[0].first = free_neighbour(mesh, edited[0].first, edited);
  const Face_index plus(Mesh::size_type(mesh.number_of_faces() / 3)), minus(Mesh::size_type(2 * mesh.number_of_faces() / 3));
  edited.emplace_back(plus, 1);
  edited.emplace_back(minus, -1);

  // 3. the field with exactly these singularities
  std::vector<std::pair<Face_index, int> > found;
  try
  {
    const SMDF::Direction_field_result r = field.compute(
      direction, CGAL::parameters::degree(4).prescribed_singularities(edited)
                   .singularities_output_iterator(std::back_inserter(found)));
    std::cout << "prescribed field: " << found.size() << " singular faces (" << edited.size()
              << " prescribed), index sum " << r.index_sum << "/4, holonomy error " << r.holonomy_error << ", "
              << r.timings.total_ms << " ms" << std::endl;
  }
  catch(const SMDF::Invalid_input_error& e)  // e.g. a pair placed where no field on the vertices can show it
  {
    std::cerr << "refused: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return found.size() == edited.size() ? EXIT_SUCCESS : EXIT_FAILURE;
}
