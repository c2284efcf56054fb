// What the command-line program direction_field prints: one line of JSON
// (--json, --json-file: the keys are a contract, only ever extended) or a
// short human-readable summary.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_REPORTS_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_REPORTS_H

#include "command_line_options.h"
#include "huge_pages_rerun.h"
#include "progress.h"
#include "file_io/read_and_repair_mesh.h"

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <ostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;

inline std::string json_escape(const std::string& s)
{
  std::string out;
  for(char c : s)
  {
    if(c == '"' || c == '\\') { out += '\\'; out += c; }
    else if(static_cast<unsigned char>(c) < 0x20) { char buf[8]; std::snprintf(buf, sizeof buf, "\\u%04x", c); out += buf; }
    else out += c;
  }
  return out;
}

inline std::string number(double x)
{
  if(!std::isfinite(x)) return "null";
  std::ostringstream os;
  os << std::setprecision(17) << x;
  return os.str();
}

// A value that may not have been computed (an eigenvalue): null if it was not.
inline std::string number(const std::optional<double>& x) { return x ? number(*x) : "null"; }

// The summary's words for a component's solve: the eigenvalue, iterations
// and residual of an eigen-solve; the system of an aligned or constrained
// field (with lambda_1 where it was computed beside it); the parallel
// section of prescribed singularities.
template <typename Report>
std::string describe_solve(const Report& c)
{
  std::ostringstream os;
  if(c.solve == SMDF::Field_solve::PARALLEL_SECTION) return "parallel section of the changed connection";
  if(c.solve == SMDF::Field_solve::LINEAR_SOLVE)
  {
    os << "linear solve (A - lambda_t M) u = M q, lambda_t = " << c.lambda;
    if(c.eigenvalue) os << " (lambda_1 = " << *c.eigenvalue << ", " << c.iterations << " iterations)";
    return os.str();
  }
  os << "eigen-solve: eigenvalue " << c.eigenvalue.value_or(0.) << ", " << c.iterations << " iterations, residual " << c.residual
     << (c.converged ? "" : " (not converged)");
  return os.str();
}

// The largest component: the one whose lambda and t the JSON reports.
inline const SMDF::Component_report& main_component(const SMDF::Direction_field_result& r)
{
  std::size_t best = 0;
  for(std::size_t i = 1; i < r.components.size(); ++i)
    if(r.components[i].number_of_vertices > r.components[best].number_of_vertices) best = i;
  return r.components[best];
}

// The outputs asked for but not written (Output_files::left_out()): option and path.
typedef std::vector<std::pair<std::string, std::string> > Left_out_outputs;

// [[l, t], ...]: the loops along which the field turns other than the nearest choice
inline std::string loop_turns_json(const SMDF::Direction_field_result& r)
{
  std::string text = "[";
  for(const auto& lt : r.loop_turns)
    text += (text.size() > 1 ? ",[" : "[") + std::to_string(lt.first) + "," + std::to_string(lt.second) + "]";
  return text + "]";
}

template <typename Mesh>
void write_json(std::ostream& os, const Options& o, const Repaired_mesh<Mesh>& input, const SMDF::Direction_field_result& r,
                const Left_out_outputs& left_out,
                const Program_timings& timings, int ranks)
{
  const Mesh& mesh = input.mesh;
  const Repair_report& rep = input.report;
  int chi = 0;
  for(const auto& c : r.components) chi += c.euler_characteristic;
  os << "{\"mesh\":\"" << json_escape(o.mesh) << "\""
     << ",\"vertices\":" << input.file_vertices << ",\"faces\":" << input.file_faces
     << ",\"mesh_vertices\":" << mesh.number_of_vertices() << ",\"mesh_faces\":" << mesh.number_of_faces()
     << ",\"components\":" << r.components.size() << ",\"isolated_vertices\":" << r.number_of_isolated_vertices
     << ",\"euler_characteristic\":" << chi << ",\"degree\":" << r.degree << ",\"s\":" << number(r.smoothness_parameter);
  auto array = [&](const char* name, auto get) {
    os << ",\"" << name << "\":[";
    for(std::size_t i = 0; i < r.components.size(); ++i) os << (i ? "," : "") << get(r.components[i]);
    os << "]";
  };
  array("eigenvalues", [](const SMDF::Component_report& c) { return number(c.eigenvalue); });
  array("solves", [](const SMDF::Component_report& c) { return std::string("\"") + solve_name(c.solve) + "\""; });
  array("component_euler_characteristics", [](const SMDF::Component_report& c) { return std::to_string(c.euler_characteristic); });
  array("component_index_sums", [](const SMDF::Component_report& c) { return std::to_string(c.index_sum); });
  array("component_low_magnitude_fractions",
        [](const SMDF::Component_report& c) { return number(c.low_magnitude_fraction); });
  os << ",\"iterations\":" << r.iterations << ",\"residual\":" << number(r.residual)
     << ",\"converged\":" << (r.converged ? "true" : "false")
     << ",\"singular_faces\":" << r.number_of_singular_faces << ",\"index_sum\":" << r.index_sum
     << ",\"mollification\":" << number(r.mollification) << ",\"tangent_plane_vertices\":" << r.tangent_plane_vertices
     << ",\"prescribed\":" << (r.prescribed ? "true" : "false") << ",\"holonomy_error\":" << number(r.holonomy_error)
     << ",\"loop_turns\":" << loop_turns_json(r) << ",\"outputs_left_out\":[";
  for(std::size_t i = 0; i < left_out.size(); ++i) os << (i ? "," : "") << "\"" << left_out[i].first << "\"";
  os << "]"
     << ",\"lambda\":" << number(main_component(r).lambda)
     << ",\"alignment_weight\":" << number(main_component(r).alignment_weight)
     << ",\"eigenvalue_bound\":" << number(main_component(r).eigenvalue)
     << ",\"repairs\":{\"merged_points\":" << rep.merged_points << ",\"degenerate_faces_removed\":" << rep.degenerate_polygons
     << ",\"polygons_triangulated\":" << rep.triangulated_polygons << ",\"triangles_from_polygons\":" << rep.triangles_from_polygons
     << ",\"repeated_faces_removed\":" << rep.repeated_triangles << ",\"faces_reoriented\":" << rep.reoriented_triangles
     << ",\"vertices_duplicated\":" << rep.duplicated_vertices << ",\"faces_skipped\":" << rep.skipped_triangles
     << ",\"unused_vertices_removed\":" << rep.unused_vertices << "}"
     << ",\"timings_ms\":{\"setup\":" << number(r.timings.setup_ms)
     << ",\"factorization\":" << number(r.timings.factorization_ms)
     << ",\"solve\":" << number(r.timings.solve_ms) << ",\"total\":" << number(r.timings.total_ms)
     << ",\"read\":" << number(timings.read) << ",\"repair\":" << number(timings.repair)
     << ",\"write\":" << number(timings.write) << "},\"io_ms\":" << number(timings.io()) << ",\"solver\":\"" << o.solver << "\",\"ranks\":" << ranks
     << ",\"huge_pages\":" << (malloc_uses_huge_pages() ? "true" : "false") << "}\n";
}

template <typename Mesh>
void write_summary(std::ostream& os, const Options& o, const Repaired_mesh<Mesh>& input, const SMDF::Direction_field_result& r,
                   const Left_out_outputs& left_out,
                   const Program_timings& timings, int ranks)
{
  const Mesh& mesh = input.mesh;
  int chi = 0;
  for(const auto& c : r.components) chi += c.euler_characteristic;
  os << "mesh            " << o.mesh << "\n"
     << "size            " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " faces, "
     << r.components.size() << " component(s), Euler characteristic " << chi << "\n"
     << "field           degree n = " << r.degree << ", s = " << r.smoothness_parameter << "\n";
  if(o.solver != "default")
    os << "solver          " << o.solver << " on " << ranks << " process" << (ranks > 1 ? "es" : "") << "\n";
  if(input.report.any())
  {
    os << "repairs         " << input.report.summary() << "\n";
    if(o.mesh_out.empty() && !(o.vtk + o.vtk_singularities + o.ply + o.rosy + o.ffield + o.singularity_list + o.streamlines).empty())
      os << "note            the exchange files describe the repaired mesh: --mesh-out FILE writes it\n";
    else if(!o.mesh_out.empty())
      os << "repaired mesh   " << o.mesh_out << " (the mesh the exchange files describe)\n";
  }
  if(main_component(r).alignment_weight > 0. || main_component(r).lambda != 0.)
  {
    os << "alignment       lambda_t = " << main_component(r).lambda;
    if(main_component(r).eigenvalue) os << " (bound lambda_1 = " << *main_component(r).eigenvalue << ")";
    os << ", alignment weight t = " << main_component(r).alignment_weight << "\n";
  }
  if(r.prescribed)
    os << "prescribed      the singular faces of " << o.prescribe << " (parallel field, holonomy error "
       << r.holonomy_error << " rad)\n";
  for(const auto& output : left_out)
    os << "not written     " << output.first << " " << output.second
       << ": nothing to show, and meshio reads no .vtu without points (an older file of that name is removed)\n";
  if(r.mollification > 0.)
    os << "mollification   " << r.mollification << " added to every edge length (degenerate faces)\n";
  if(r.tangent_plane_vertices > 0)
    os << "folded faces    " << r.tangent_plane_vertices << " vertices around triangles folded over the surface, "
       << "measured in the surface's fitted tangent plane so that they add no singularity\n";
  for(std::size_t i = 0; i < r.components.size() && i < 10; ++i)
  {
    const auto& c = r.components[i];
    os << "component " << std::setw(4) << i << "  " << describe_solve(c) << ", " << c.number_of_singular_faces
       << " singular faces, index sum " << c.index_sum << "/" << r.degree;
    if(c.low_magnitude_fraction > 0.)
      os << "; at " << 100. * c.low_magnitude_fraction << "% of its vertices the field is too weak for its "
         << "directions to be exact";
    os << "\n";
  }
  if(r.components.size() > 10) os << "...             (" << r.components.size() - 10 << " more components)\n";
  bool closed = true;
  for(const auto& c : r.components) closed = closed && c.is_closed;
  os << "singularities   " << r.number_of_singular_faces << " faces, index sum " << r.index_sum << "/" << r.degree;
  if(closed) os << " (= n times the Euler characteristic, as on every closed mesh)\n";
  else os << " (with a boundary any sum can occur: n times the Euler characteristic, " << r.degree * chi << "/"
          << r.degree << ", holds on closed meshes only)\n";
  os
     << "time            " << std::fixed << std::setprecision(1) << r.timings.total_ms << " ms (setup "
     << r.timings.setup_ms << ", factorization " << r.timings.factorization_ms << ", solve " << r.timings.solve_ms
     << "); files " << timings.io() << " ms (read " << timings.read << ", repair " << timings.repair << ", write "
     << timings.write << ")\n";
}

#endif
