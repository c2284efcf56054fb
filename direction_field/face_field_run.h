// --on faces: the field on the faces of the repaired mesh, with its singular
// vertices and its matching, the files quad meshers read (.rosy, .ffield,
// .sharp) and Directional reads (.rawfield, .sing, .matching), and those of
// viewers (--vtk, --vtk-singularities, --streamlines, --png).
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_FACE_FIELD_RUN_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_FACE_FIELD_RUN_H

#include "command_line_options.h"
#include "exchange_files.h"
#include "file_io/output_files.h"
#include "file_io/read_and_repair_mesh.h"
#include "png_snapshot.h"
#include "reports.h"

#include <CGAL/Surface_mesh_direction_fields/feature_edges.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <functional>
#include <algorithm>
#include <vector>

namespace face_field_run {

namespace SMDF = CGAL::Surface_mesh_direction_fields;

// The mesh and the field on its faces as the files write them.
template <typename Mesh>
SMDF::Direction_field_data field_data(const Mesh& mesh, int degree)
{
  SMDF::Direction_field_data data;
  data.degree = degree;
  for(auto v : mesh.vertices()) data.points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
  for(auto f : mesh.faces())
  {
    std::array<std::size_t, 3> t;
    int c = 0;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[c++] = v;
    data.faces.push_back(t);
  }
  return data;
}

// The feature edges of --feature-angle (the package's scale-safe detection), as vertex pairs.
template <typename Mesh>
std::vector<std::array<std::size_t, 2> > feature_edges(const Options& o, const Mesh& mesh,
                                                      std::vector<unsigned char>& is_feature)
{
  is_feature.assign(mesh.number_of_edges(), 0);
  std::vector<std::array<std::size_t, 2> > edges;
  if(!(o.feature_angle > 0.)) return edges;
  SMDF::detect_feature_edges(mesh, o.feature_angle, CGAL::make_property_map(is_feature),
                             CGAL::parameters::feature_cleanup_steps(o.feature_cleanup));
  for(auto e : mesh.edges())
    if(is_feature[e]) edges.push_back({mesh.source(mesh.halfedge(e)), mesh.target(mesh.halfedge(e))});
  return edges;
}

// --constrain-boundary as the library's enumeration (both fields).
inline SMDF::Boundary_alignment boundary_alignment(const Options& o)
{
  return o.constrain_boundary == "tangent"  ? SMDF::Boundary_alignment::TANGENT
         : o.constrain_boundary == "normal" ? SMDF::Boundary_alignment::NORMAL
                                            : SMDF::Boundary_alignment::NONE;
}

struct Face_field
{
  std::vector<std::array<std::size_t, 2> > features;  // of --feature-angle, detected once for the field and --sharp
  SMDF::Face_direction_field_result result;
  SMDF::Direction_field_data data;
};

// The library call with the options' named parameters; the matching per face side.
// `point_of_vertex`: the point each vertex copies (the file's vertex where
// non-manifold edges are glued, else the vertex itself).
template <typename Mesh>
Face_field compute(const Options& o, const Mesh& mesh, const std::vector<std::size_t>& point_of_vertex,
                   const std::vector<std::pair<typename Mesh::Vertex_index, int> >* prescription,
                   const std::function<bool(double)>& progress)
{
  typedef typename Mesh::Vertex_index Vertex_index;
  Face_field field;
  std::vector<unsigned char> is_feature;
  field.features = feature_edges(o, mesh, is_feature);
  std::vector<typename CGAL::Kernel_traits<typename Mesh::Point>::Kernel::Vector_3> directions(mesh.number_of_faces());
  std::vector<int> matching(mesh.number_of_edges(), 0);
  std::vector<std::pair<Vertex_index, int> > singular;
  auto np = CGAL::parameters::degree(o.degree)
              .random_seed(o.seed)
              .number_of_iterations(o.max_iterations)
              .residual_tolerance(o.tolerance)
              .principal_curvature_alignment(curvature_alignment(o))
              .boundary_alignment(boundary_alignment(o))
              .edge_is_feature_map(CGAL::make_property_map(is_feature))
              .singularities_output_iterator(std::back_inserter(singular))
              .edge_matching_map(CGAL::make_property_map(matching))
              .singularity_cancellation_radius(o.cancel_singularities)
              .vertex_point_index_map(CGAL::make_property_map(point_of_vertex))
              .progress_callback(progress);
  auto direction_map = CGAL::make_property_map(directions);
  if(prescription)
    field.result = SMDF::compute_globally_optimal_face_directions(mesh, direction_map,
                                                                  np.prescribed_singularities(*prescription));
  else if(o.weight_given)
    field.result = SMDF::compute_globally_optimal_face_directions(mesh, direction_map, np.alignment_weight(o.weight));
  else if(o.lambda_given)
    field.result = SMDF::compute_globally_optimal_face_directions(mesh, direction_map, np.alignment_lambda(o.lambda));
  else
    field.result = SMDF::compute_globally_optimal_face_directions(mesh, direction_map, np);
  field.data = SMDF::make_face_direction_field_data(mesh, direction_map, field.result, singular,
                                                    CGAL::parameters::edge_matching_map(CGAL::make_property_map(matching)));
  return field;
}

// The files of a field on faces.
inline void write_files(const Options& o, const Face_field& field, Output_files& outputs)
{
  if(!o.rosy.empty()) SMDF::IO::write_rosy(outputs.stream(o.rosy), field.data);
  if(!o.ffield.empty()) SMDF::IO::write_ffield(outputs.stream(o.ffield), field.data);
  if(!o.rawfield.empty()) SMDF::IO::write_rawfield(outputs.stream(o.rawfield), field.data);
  if(!o.sing.empty()) SMDF::IO::write_vertex_singularities(outputs.stream(o.sing), field.data);
  if(!o.matching.empty()) SMDF::IO::write_matching(outputs.stream(o.matching), field.data);
  if(!o.singularities.empty())
  {
    std::ostream& os = outputs.stream(o.singularities);
    for(const auto& vk : field.data.vertex_singularities) os << vk.first << " " << vk.second << "\n";
  }
  if(!o.sharp.empty()) SMDF::IO::write_sharp(outputs.stream(o.sharp), field.data, field.features);
  if(!o.vtk.empty())
  {
    if(soup_reading::lower_case_extension(o.vtk) == "vtu") SMDF::IO::write_VTU(outputs.stream(o.vtk), field.data);
    else SMDF::IO::write_VTK(outputs.stream(o.vtk), field.data);
  }
  // as for vertex fields (exchange_files.h): no .vtu without a point, meshio reads none
  const bool vtu_markers = soup_reading::lower_case_extension(o.vtk_singularities) == "vtu";
  if(!o.vtk_singularities.empty() && vtu_markers && field.data.vertex_singularities.empty())
    outputs.leave_out(o.vtk_singularities);
  else if(!o.vtk_singularities.empty())
  {
    if(vtu_markers) SMDF::IO::write_VTU_singularities(outputs.stream(o.vtk_singularities), field.data);
    else SMDF::IO::write_VTK_singularities(outputs.stream(o.vtk_singularities), field.data);
  }
}

// --streamlines, and the lines --png draws: traced on the per-face field itself.
inline std::vector<SMDF::Streamline> write_streamlines(const Options& o, const Face_field& field, Output_files& outputs)
{
  if(o.streamlines.empty()) return std::vector<SMDF::Streamline>();
  std::vector<SMDF::Streamline> lines = SMDF::trace_streamlines(field.data);
  if(lines.empty() && soup_reading::lower_case_extension(o.streamlines) == "vtu") outputs.leave_out(o.streamlines);
  else exchange_files::write_streamlines(o.streamlines, outputs.stream(o.streamlines), lines, field.data.degree);
  return lines;
}

// --png: the shaded mesh, the directions at the faces' centres (or the field
// lines), the singular vertices.
inline void write_picture(const Options& o, const Face_field& field, const std::vector<SMDF::Streamline>& lines,
                          Output_files& outputs)
{
  png_snapshot::Scene scene;
  scene.degree = field.data.degree;
  scene.points = field.data.points;
  scene.triangles = field.data.faces;
  scene.directions = field.data.face_directions;
  scene.directions_on_faces = true;
  scene.vertex_index.assign(field.data.points.size(), 0);
  for(const auto& vk : field.data.vertex_singularities) scene.vertex_index[vk.first] = vk.second;
  for(const SMDF::Streamline& l : lines) scene.polylines.push_back(l.points);
  scene.feature_edges = field.features;
  png_snapshot::render(scene, outputs.stream(o.png));
}

// The singular vertices whose k is a multiple of n (index +-1, +-2, ...): a
// reader that recomputes the matching and reads the vertex's turning modulo n
// (QuadWild, vcglib's UpdateSingularByCross) sees no singularity there.
inline std::size_t hidden_modulo_n(const SMDF::Direction_field_data& data)
{
  std::size_t hidden = 0;
  for(const auto& vk : data.vertex_singularities) hidden += vk.second % data.degree == 0;
  return hidden;
}

// One line of JSON (the keys of direction_field/README.md, "--on faces").
template <typename Mesh>
void write_json(std::ostream& os, const Options& o, const Repaired_mesh<Mesh>& input, const Face_field& field,
                const Output_files& outputs, const Program_timings& timings)
{
  const SMDF::Face_direction_field_result& r = field.result;
  long long chi = 0, boundary = 0;
  for(const auto& c : r.components) { chi += c.euler_characteristic; boundary += c.boundary_index; }
  os << "{\"mesh\":\"" << json_escape(o.mesh) << "\",\"field_location\":\"faces\""
     << ",\"vertices\":" << input.file_vertices << ",\"faces\":" << input.file_faces
     << ",\"mesh_vertices\":" << input.mesh.number_of_vertices() << ",\"mesh_faces\":" << input.mesh.number_of_faces()
     << ",\"components\":" << r.components.size() << ",\"euler_characteristic\":" << chi << ",\"degree\":" << r.degree
     << ",\"eigenvalues\":[";
  for(std::size_t i = 0; i < r.components.size(); ++i) os << (i ? "," : "") << number(r.components[i].eigenvalue);
  os << "],\"solves\":[";
  for(std::size_t i = 0; i < r.components.size(); ++i)
    os << (i ? "," : "") << "\"" << solve_name(r.components[i].solve) << "\"";
  os << "],\"iterations\":" << r.iterations << ",\"residual\":" << number(r.residual)
     << ",\"converged\":" << (r.converged ? "true" : "false")
     << ",\"singular_vertices\":" << r.number_of_singular_vertices << ",\"index_sum\":" << r.index_sum
     << ",\"boundary_index\":" << boundary << ",\"mollification\":" << number(r.mollification)
     << ",\"singular_vertices_multiple_of_n\":" << hidden_modulo_n(field.data)
     << ",\"prescribed\":" << (r.prescribed ? "true" : "false")
     << ",\"non_principal_jumps\":" << r.number_of_non_principal_jumps
     << ",\"cancelled_pairs\":" << r.number_of_cancelled_pairs << ",\"glued_edges\":" << r.number_of_glued_edges
     << ",\"outputs_left_out\":[";
  const auto left_out = outputs.left_out();
  for(std::size_t i = 0; i < left_out.size(); ++i) os << (i ? "," : "") << "\"" << left_out[i].first << "\"";
  os << "]"
     << ",\"timings_ms\":{\"setup\":" << number(r.timings.setup_ms)
     << ",\"factorization\":" << number(r.timings.factorization_ms) << ",\"solve\":" << number(r.timings.solve_ms)
     << ",\"total\":" << number(r.timings.total_ms) << ",\"read\":" << number(timings.read)
     << ",\"repair\":" << number(timings.repair) << ",\"write\":" << number(timings.write) << "}"
     << ",\"huge_pages\":" << (malloc_uses_huge_pages() ? "true" : "false") << "}\n";
}

template <typename Mesh>
void write_summary(std::ostream& os, const Options& o, const Repaired_mesh<Mesh>& input, const Face_field& field)
{
  const SMDF::Face_direction_field_result& r = field.result;
  os << "mesh            " << o.mesh << "\n"
     << "size            " << input.mesh.number_of_vertices() << " vertices, " << input.mesh.number_of_faces()
     << " faces, " << r.components.size() << " component(s)\n"
     << "field           on faces, degree n = " << r.degree << "\n";
  if(input.report.any()) os << "repairs         " << input.report.summary() << "\n";
  if(r.number_of_glued_edges > 0)
    os << "glued           " << r.number_of_glued_edges << " non-manifold edges: their faces share the field "
       << "(--non-manifold cut keeps the pieces apart)\n";
  for(std::size_t i = 0; i < r.components.size() && i < 10; ++i)
  {
    const auto& c = r.components[i];
    os << "component " << i << "  " << describe_solve(c) << ", " << c.number_of_singular_vertices
       << " singular vertices, index sum " << c.index_sum << "/" << r.degree
       << " (boundary " << c.boundary_index << "/" << r.degree << ", Euler characteristic " << c.euler_characteristic
       << ")\n";
  }
  if(r.number_of_cancelled_pairs > 0 && !r.prescribed)
    os << "cancelled       " << r.number_of_cancelled_pairs << " pairs of opposite singular vertices within "
       << o.cancel_singularities << " of the diagonal (the field turned off its constrained faces)\n";
  else if(r.number_of_cancelled_pairs > 0)
    os << "cancelled       " << r.number_of_cancelled_pairs << " pairs of opposite singular vertices within "
       << o.cancel_singularities << " of the diagonal (parallel field with the others; "
       << r.number_of_non_principal_jumps << " edges with a matching other than the principal one)\n";
  else if(r.prescribed)
    os << "prescribed      the singular vertices of " << o.prescribe << " (parallel field; "
       << r.number_of_non_principal_jumps << " edges with a matching other than the principal one)\n";
  if(const std::size_t hidden = hidden_modulo_n(field.data))
    os << "note            " << hidden << " singular vertices have an index k that is a multiple of n: readers that "
       << "recompute the matching modulo n (QuadWild) see no singularity there\n";
  os << "timings         " << compact(r.timings.total_ms) << " ms\n";
}

} // namespace face_field_run

#endif
