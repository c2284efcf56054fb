// One program, two files built with different default solvers: this one
// with the package's (CHOLMOD when found) and the compiled engine,
// test_default_solvers_eigen.cpp without CHOLMOD and header-only. The free
// function compute_globally_optimal_directions() with the same template
// arguments is then two distinct functions (the inline namespace of
// Globally_optimal_direction_field.h), each computing with its own default;
// without that namespace the linker keeps one of them for both files.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include "test_types.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;

// in test_default_solvers_eigen.cpp
const void* free_function_of_eigen_file();
int singular_faces_of_eigen_file(int& index_sum, std::string& solver);

static const void* free_function_of_this_file()
{
  typedef Mesh::Property_map<Mesh::Vertex_index, Kernel::Vector_3> Map;
  typedef decltype(CGAL::parameters::degree(4)) Parameters;
  SMDF::Direction_field_result (*f)(const Mesh&, Map, const Parameters&) = &SMDF::compute_globally_optimal_directions;
  return reinterpret_cast<const void*>(f);
}

int main()
{
  Test_report report("default_solvers");
  Mesh mesh;
  make_icosphere(mesh, 3);
  auto directions = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:d", CGAL::NULL_VECTOR).first;
  const SMDF::Direction_field_result here =
    SMDF::compute_globally_optimal_directions(mesh, directions, CGAL::parameters::degree(4));
  int index_sum = 0;
  std::string eigen_file_solver;
  const int there = singular_faces_of_eigen_file(index_sum, eigen_file_solver);
  report.check(free_function_of_this_file() != free_function_of_eigen_file(),
               "two default solvers: two distinct free functions");
  report.check(eigen_file_solver != typeid(SMDF::Default_direction_field_solver*).name(),
               "the two files name two solvers as their default");
  report.check(here.index_sum == 8 && index_sum == 8 && static_cast<int>(here.number_of_singular_faces) == there,
               "each file's field: Poincare-Hopf, the same number of singular faces (" +
                 std::to_string(here.number_of_singular_faces) + ", " + std::to_string(there) + ")");
  return report.finish();
}
