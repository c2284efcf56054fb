// The largest component of a Surface_mesh with its tangent spaces and
// connection for n = 4, for the benchmarks of the distributed path.
#ifndef SMDF_BENCHMARK_LARGEST_COMPONENT_H
#define SMDF_BENCHMARK_LARGEST_COMPONENT_H

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include <cstddef>

template <typename Mesh>
struct Largest_component
{
  typedef CGAL::Surface_mesh_direction_fields::internal::Indexed_mesh Indexed_mesh;
  Indexed_mesh m;
  CGAL::Surface_mesh_direction_fields::internal::Tangent_spaces ts;
  CGAL::Surface_mesh_direction_fields::internal::Connection con;
  CGAL::Surface_mesh_direction_fields::internal::Components comps;
  std::size_t largest = 0;

  explicit Largest_component(const Mesh& mesh)
    : m(CGAL::Surface_mesh_direction_fields::internal::make_indexed_mesh(
        mesh,
        [&](typename Mesh::Vertex_index v) {
          const auto& p = mesh.point(v);
          return CGAL::Surface_mesh_direction_fields::internal::Vec3{p.x(), p.y(), p.z()};
        },
        get(CGAL::vertex_index, mesh), get(CGAL::face_index, mesh))),
      ts(CGAL::Surface_mesh_direction_fields::internal::compute_tangent_spaces(m)),
      con(CGAL::Surface_mesh_direction_fields::internal::compute_connection(m, ts, 4)),
      comps(CGAL::Surface_mesh_direction_fields::internal::split_into_components(m))
  {
    for(std::size_t c = 1; c < comps.list.size(); ++c)
      if(comps.list[c].vertices.size() > comps.list[largest].vertices.size()) largest = c;
  }
  const CGAL::Surface_mesh_direction_fields::internal::Component& component() const { return comps.list[largest]; }

  // A and M of the component, for the energy E_s
  CGAL::Surface_mesh_direction_fields::internal::Energy_and_mass matrices(double s) const
  {
    return CGAL::Surface_mesh_direction_fields::internal::assemble_energy_and_mass(m, ts, con, component(),
                                                                                  comps.local_index, s);
  }
};

#endif // SMDF_BENCHMARK_LARGEST_COMPONENT_H
