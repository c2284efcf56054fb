// OpenMesh through CGAL's graph traits: the same eigenvalue and singularities
// as a Surface_mesh with the same vertices and faces.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_PolyMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include "test_types.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <boost/property_map/property_map.hpp>

#include <iomanip>
#include <map>
#include <vector>

// double precision points (OpenMesh's default is float)
struct Double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::PolyMesh_ArrayKernelT<Double_traits> Open_mesh;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

int main()
{
  Test_report report("OpenMesh");
  Mesh mesh;
  make_icosphere(mesh, 3);
  for(auto v : mesh.vertices())  // no symmetry
  {
    const Kernel::Vector_3 p = mesh.point(v) - CGAL::ORIGIN;
    mesh.point(v) = CGAL::ORIGIN + (1. + 0.2 * std::sin(3. * p.x()) * std::cos(2. * p.y() + p.z())) * p;
  }
  auto dir = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:d").first;
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(mesh, dir, CGAL::parameters::degree(4));

  Open_mesh om;
  CGAL::copy_face_graph(mesh, om);
  typedef CGAL::Kernel_traits<boost::property_traits<boost::property_map<Open_mesh, CGAL::vertex_point_t>::type>::value_type>::Kernel OM_kernel;  // Epick
  std::map<boost::graph_traits<Open_mesh>::vertex_descriptor, OM_kernel::Vector_3> storage;
  std::vector<std::pair<boost::graph_traits<Open_mesh>::face_descriptor, int> > sing;
  const SMDF::Direction_field_result ro = SMDF::compute_globally_optimal_directions(
    om, boost::make_assoc_property_map(storage),
    CGAL::parameters::degree(4).singularities_output_iterator(std::back_inserter(sing)));
  std::cout << std::setprecision(17) << "Surface_mesh " << r.components[0].eigenvalue.value() << ", OpenMesh " << ro.components[0].eigenvalue.value() << std::endl;
  report.check(std::abs(ro.components[0].eigenvalue.value() - r.components[0].eigenvalue.value()) <= 1e-7 * r.components[0].eigenvalue.value(),  // the points pass through OpenMesh's own types
               "OpenMesh: same eigenvalue");
  report.check(ro.index_sum == 8 && sing.size() == ro.number_of_singular_faces && storage.size() == om.n_vertices(),
               "OpenMesh: Poincare-Hopf and one direction per vertex");
  bool unit = true;
  for(const auto& vd : storage) unit = unit && std::abs(vd.second.squared_length() - 1.) < 1e-12;
  report.check(unit, "OpenMesh: unit outputs");
  return report.finish();
}
