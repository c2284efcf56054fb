// The second file of test_default_solvers: built without
// CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD and header-only, so its
// default solver is Eigen's SimplicialLDLT.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include "test_types.h"
#include "generated_meshes.h"

#include <string>
#include <typeinfo>

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#error "test_default_solvers_eigen.cpp must be built without CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD"
#endif

namespace SMDF = CGAL::Surface_mesh_direction_fields;

const void* free_function_of_eigen_file()
{
  typedef Mesh::Property_map<Mesh::Vertex_index, Kernel::Vector_3> Map;
  typedef decltype(CGAL::parameters::degree(4)) Parameters;
  SMDF::Direction_field_result (*f)(const Mesh&, Map, const Parameters&) = &SMDF::compute_globally_optimal_directions;
  return reinterpret_cast<const void*>(f);
}

int singular_faces_of_eigen_file(int& index_sum, std::string& solver)
{
  Mesh mesh;
  make_icosphere(mesh, 3);
  auto directions = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:d", CGAL::NULL_VECTOR).first;
  const SMDF::Direction_field_result r =
    SMDF::compute_globally_optimal_directions(mesh, directions, CGAL::parameters::degree(4));
  index_sum = static_cast<int>(r.index_sum);
  solver = typeid(SMDF::Default_direction_field_solver*).name();
  return static_cast<int>(r.number_of_singular_faces);
}
