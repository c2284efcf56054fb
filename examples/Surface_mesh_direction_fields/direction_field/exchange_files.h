// The files of the repaired mesh that other programs open: --vtk and
// --vtk-singularities (.vtk or .vtu), --ply, --rosy, --ffield, --singularity-list (written by the library's
// IO/direction_field_files.h), the field lines of --streamlines in the format
// their file name asks for, and the repaired mesh itself (--mesh-out).
#ifndef SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_EXCHANGE_FILES_H
#define SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_EXCHANGE_FILES_H

#include "command_line_options.h"
#include <CGAL/Surface_mesh_direction_fields/internal/number_writer.h>
#include "output_files.h"
#include "read_polygon_soup.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include <ostream>
#include <string>
#include <vector>

namespace exchange_files {

namespace SMDF = CGAL::Surface_mesh_direction_fields;

// VTK XML cells of field lines: point coordinates, then the cells.
inline void write_streamline_points(std::ostream& os, const std::vector<SMDF::Streamline>& lines)
{
  os << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  SMDF::internal::Number_writer w(os);
  for(const SMDF::Streamline& l : lines)
    for(const auto& p : l.points) w.line(p[0], p[1], p[2]);
  w.flush();
  os << "</DataArray>\n</Points>\n";
}

inline void write_streamline_connectivity(std::ostream& os, const std::vector<SMDF::Streamline>& lines)
{
  SMDF::internal::Number_writer w(os);
  w.text("<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  std::size_t point = 0;
  for(const SMDF::Streamline& l : lines)
  {
    for(std::size_t i = 0; i < l.points.size(); ++i) w.integer(static_cast<long long>(point++)).space();
    w.end_line();
  }
  w.text("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  point = 0;
  for(const SMDF::Streamline& l : lines) w.integer(static_cast<long long>(point += l.points.size())).end_line();
  w.text("</DataArray>\n");
}

// .vtp: PolyData, one poly-line per field line.
inline void write_streamlines_VTP(std::ostream& os, const std::vector<SMDF::Streamline>& lines)
{
  std::size_t points = 0;
  for(const SMDF::Streamline& l : lines) points += l.points.size();
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
     << "<PolyData>\n<Piece NumberOfPoints=\"" << points << "\" NumberOfLines=\"" << lines.size() << "\">\n";
  write_streamline_points(os, lines);
  os << "<Lines>\n";
  write_streamline_connectivity(os, lines);
  os << "</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

// .vtu or .vtk: an unstructured grid of line segments (VTK_LINE), which
// meshio keeps (it drops poly-lines); the cell data "line" numbers the field
// line each segment belongs to.
inline void write_streamline_segments(std::ostream& os, const std::vector<SMDF::Streamline>& lines, int degree,
                                      bool xml)
{
  SMDF::internal::VTK_grid g;
  g.title = "field lines of a direction field of degree " + std::to_string(degree) +
            " (CGAL Surface_mesh_direction_fields)";
  g.degree = degree;
  SMDF::internal::VTK_array line{"line", 1, {}};
  for(std::size_t i = 0; i < lines.size(); ++i)
  {
    const long long first = static_cast<long long>(g.points.size());
    g.points.insert(g.points.end(), lines[i].points.begin(), lines[i].points.end());
    for(long long j = 1; j < static_cast<long long>(lines[i].points.size()); ++j)
    {
      g.add_cell({first + j - 1, first + j}, 3);
      line.values.push_back(static_cast<double>(i));
    }
  }
  g.cell_arrays.push_back(std::move(line));
  if(xml) SMDF::internal::write_XML_grid(os, g);
  else SMDF::internal::write_legacy_grid(os, g);
}

// OBJ: the points as "v", each line as "l i j k ...".
inline void write_streamlines_OBJ(std::ostream& os, const std::vector<SMDF::Streamline>& lines)
{
  SMDF::internal::Number_writer w(os);
  w.text("# field lines of a direction field (CGAL Surface_mesh_direction_fields)\n");
  for(const SMDF::Streamline& l : lines)
    for(const auto& p : l.points) w.text("v ").number(p[0]).space().number(p[1]).space().number(p[2]).end_line();
  long long next = 1;
  for(const SMDF::Streamline& l : lines)
  {
    w.text("l");
    for(std::size_t i = 0; i < l.points.size(); ++i) w.space().integer(next++);
    w.end_line();
  }
}

// CGAL's polylines text format: "N x1 y1 z1 ... xN yN zN" per line.
inline void write_streamlines_text(std::ostream& os, const std::vector<SMDF::Streamline>& lines)
{
  SMDF::internal::Number_writer w(os);
  for(const SMDF::Streamline& l : lines)
  {
    w.integer(static_cast<long long>(l.points.size()));
    for(const auto& p : l.points) w.space().number(p[0]).space().number(p[1]).space().number(p[2]);
    w.end_line();
  }
}

inline void write_streamlines(const std::string& path, std::ostream& os, const std::vector<SMDF::Streamline>& lines,
                              int degree)
{
  const std::string extension = soup_reading::lower_case_extension(path);
  if(extension == "vtp") write_streamlines_VTP(os, lines);
  else if(extension == "vtu" || extension == "vtk") write_streamline_segments(os, lines, degree, extension == "vtu");
  else if(extension == "obj") write_streamlines_OBJ(os, lines);
  else write_streamlines_text(os, lines);
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
