// The files of the repaired mesh that other programs open: --vtk and
// --vtk-singularities (.vtk or .vtu), --ply, --rosy, --ffield, --singularity-list (written by the library's
// IO/direction_field_files.h), the field lines of --streamlines in the format
// their file name asks for, and the repaired mesh itself (--mesh-out).
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_EXCHANGE_FILES_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_EXCHANGE_FILES_H

#include "command_line_options.h"
#include "file_io/output_files.h"
#include "file_io/read_polygon_soup.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include <ostream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace exchange_files {

namespace SMDF = CGAL::Surface_mesh_direction_fields;

inline void write_streamlines(const std::string& path, std::ostream& os, const std::vector<SMDF::Streamline>& lines,
                              int degree)
{
  const std::string extension = soup_reading::lower_case_extension(path);
  if(extension == "vtp") SMDF::IO::write_field_lines_VTP(os, lines);
  else if(extension == "vtu") SMDF::IO::write_field_lines_VTU(os, lines, degree);
  else if(extension == "vtk") SMDF::IO::write_field_lines_VTK(os, lines, degree);
  else if(extension == "obj") SMDF::IO::write_field_lines_OBJ(os, lines);
  else SMDF::IO::write_field_lines_polylines(os, lines);
}

// --vtk and --vtk-singularities write VTK's XML format for a .vtu name and
// the legacy format for any other: a name with another extension is written,
// as it always was, with a warning that says which format it holds.
inline void warn_about_vtk_names(const std::string& vtk, const std::string& vtk_singularities)
{
  for(const auto& [option, path] : {std::pair<const char*, const std::string&>("--vtk", vtk),
                                    std::pair<const char*, const std::string&>("--vtk-singularities", vtk_singularities)})
  {
    const std::string extension = soup_reading::lower_case_extension(path);
    if(!extension.empty() && extension != "vtk" && extension != "vtu")  // not for devices such as /dev/stdout
      std::cerr << "direction_field: warning: " << option << " '" << path
                << "' is written in VTK's legacy format (.vtk); a .vtu name gives VTK's XML format\n";
  }
}

// --mesh-out writes OFF, OBJ or PLY, chosen by the name (write_mesh()):
// another name is refused (checked once the outputs are known to be
// writable paths).
inline void check_mesh_out_name(const std::string& path)
{
  const std::string extension = soup_reading::lower_case_extension(path);
  if(!path.empty() && extension != "off" && extension != "obj" && extension != "ply")
    throw Usage_error("--mesh-out writes .off, .obj or .ply files, not '" + path + "'");
}

// --mesh-out: .off, .obj or .ply, coordinates exact (17 digits).
template <typename Mesh>
void write_mesh(const std::string& path, std::ostream& os, const Mesh& mesh)
{
  const std::string extension = soup_reading::lower_case_extension(path);
  const auto np = CGAL::parameters::stream_precision(17);
  if(extension == "obj") CGAL::IO::write_OBJ(os, mesh, np);
  else if(extension == "ply") CGAL::IO::write_PLY(os, mesh, np.use_binary_mode(false));
  else CGAL::IO::write_OFF(os, mesh, np);
}


} // namespace exchange_files

// The exchange files the options ask for; returns the field lines (traced
// only for --streamlines or to be drawn by --png).
template <typename Mesh, typename Vector, typename Singularities>
std::vector<CGAL::Surface_mesh_direction_fields::Streamline>
write_exchange_files(const Options& o, const Mesh& mesh, const std::vector<Vector>& directions,
                     const std::vector<double>& magnitudes, const Singularities& singular_faces,
                     const CGAL::Surface_mesh_direction_fields::Direction_field_result& result, Output_files& outputs)
{
  namespace SMDF = CGAL::Surface_mesh_direction_fields;
  std::vector<SMDF::Streamline> streamlines;
  if(!o.mesh_out.empty()) exchange_files::write_mesh(o.mesh_out, outputs.stream(o.mesh_out), mesh);
  if(o.vtk.empty() && o.vtk_singularities.empty() && o.ply.empty() && o.rosy.empty() && o.ffield.empty() && o.singularity_list.empty() &&
     o.streamlines.empty())
    return streamlines;
  const SMDF::Direction_field_data data = SMDF::make_direction_field_data(
    mesh, CGAL::make_property_map(directions), result, singular_faces,
    CGAL::parameters::vertex_magnitude_map(CGAL::make_property_map(magnitudes)));
  if(!o.vtk.empty())
  {
    if(soup_reading::lower_case_extension(o.vtk) == "vtu") SMDF::IO::write_VTU(outputs.stream(o.vtk), data);
    else SMDF::IO::write_VTK(outputs.stream(o.vtk), data);
  }
  // A .vtu with no point is what VTK writes for an empty dataset, but meshio
  // reads no empty UnstructuredGrid: such an output is left out, and the
  // summary and the JSON say so (a legacy .vtk with no point is written).
  const bool vtu_markers = soup_reading::lower_case_extension(o.vtk_singularities) == "vtu";
  if(!o.vtk_singularities.empty() && vtu_markers && data.singularities.empty()) outputs.leave_out(o.vtk_singularities);
  else if(!o.vtk_singularities.empty())
  {
    if(vtu_markers) SMDF::IO::write_VTU_singularities(outputs.stream(o.vtk_singularities), data);
    else SMDF::IO::write_VTK_singularities(outputs.stream(o.vtk_singularities), data);
  }
  if(!o.ply.empty()) SMDF::IO::write_PLY(outputs.stream(o.ply), data);
  if(!o.rosy.empty()) SMDF::IO::write_rosy(outputs.stream(o.rosy), data);
  if(!o.ffield.empty()) SMDF::IO::write_ffield(outputs.stream(o.ffield), data);
  if(!o.singularity_list.empty()) SMDF::IO::write_singularities(outputs.stream(o.singularity_list), data);
  if(o.streamlines.empty()) return streamlines;
  streamlines = SMDF::trace_streamlines(data);  // the library's defaults: evenly spaced lines
  if(streamlines.empty() && soup_reading::lower_case_extension(o.streamlines) == "vtu")
    outputs.leave_out(o.streamlines);
  else exchange_files::write_streamlines(o.streamlines, outputs.stream(o.streamlines), streamlines, data.degree);
  return streamlines;
}

#endif
