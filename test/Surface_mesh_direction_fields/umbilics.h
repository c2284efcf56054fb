// The umbilics of a triaxial ellipsoid and the singular faces of its
// maximum-curvature line field found at them (test_alignment,
// test_folded_triangulations).
#ifndef SURFACE_MESH_DIRECTION_FIELDS_UMBILICS_H
#define SURFACE_MESH_DIRECTION_FIELDS_UMBILICS_H

#include <CGAL/Surface_mesh_direction_fields.h>

#include "field_checks.h"
#include "generated_meshes.h"

#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

// The singular faces of the curvature line field (n = 2) of an ellipsoid at
// alignment weight t, and how many of them are of index +1/2 within two edge
// lengths of an umbilic, one per umbilic.
struct Umbilic_count
{
  std::size_t singular_faces = 0, near_umbilics = 0;
  int index_sum = 0;
};

template <typename Mesh>
Umbilic_count umbilic_singularities(Mesh& mesh, double a, double b, double c, double t,
                                    CGAL::Surface_mesh_direction_fields::Principal_curvature_estimate estimate =
                                      CGAL::Surface_mesh_direction_fields::Principal_curvature_estimate::QUADRIC_FIT)
{
  typedef typename Mesh::Point Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3 Vector_3;
  namespace SMDF = CGAL::Surface_mesh_direction_fields;
  namespace params = CGAL::parameters;
  // umbilics: (+-x0, 0, +-z0)
  const double x0 = a * std::sqrt((a * a - b * b) / (a * a - c * c));
  const double z0 = c * std::sqrt((b * b - c * c) / (a * a - c * c));
  const std::vector<Point_3> umbilics = {Point_3(x0, 0, z0), Point_3(-x0, 0, z0), Point_3(x0, 0, -z0), Point_3(-x0, 0, -z0)};
  const double edge = mean_edge_length(mesh);
  auto d = direction_map(mesh, "v:umbilic_field");
  std::vector<std::pair<typename Mesh::Face_index, int> > sing;
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
    mesh, d, params::degree(2).principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM)
               .principal_curvature_estimate(estimate).alignment_weight(t)
               .singularities_output_iterator(std::back_inserter(sing)));
  mesh.remove_property_map(d);
  Umbilic_count count;
  count.singular_faces = sing.size();
  count.index_sum = r.index_sum;
  std::vector<bool> found(4, false);
  for(const auto& fk : sing)
  {
    Vector_3 centre = CGAL::NULL_VECTOR;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(fk.first), mesh)) centre = centre + (mesh.point(v) - CGAL::ORIGIN) / 3.;
    std::size_t which = 0;
    for(std::size_t k = 1; k < 4; ++k)
      if(CGAL::squared_distance(CGAL::ORIGIN + centre, umbilics[k]) < CGAL::squared_distance(CGAL::ORIGIN + centre, umbilics[which]))
        which = k;
    const double distance = std::sqrt(CGAL::squared_distance(CGAL::ORIGIN + centre, umbilics[which]));
    if(fk.second == 1 && distance <= 2. * edge && !found[which])
    {
      found[which] = true;
      ++count.near_umbilics;
    }
  }
  return count;
}

#endif // SURFACE_MESH_DIRECTION_FIELDS_UMBILICS_H
