// The exchange writers for Python: write_vtk(), write_vtk_singularities(),
// write_ply(), write_rosy(), write_ffield(), write_singularity_list(), each
// (path, V, F, result), and for a field on faces (path, V, F, face field)
// write_vtk(), write_vtk_singularities(), write_rosy(), write_ffield(),
// write_rawfield(), write_sing(), write_matching(), as the command-line program writes them (the library's
// IO::write_*() on make_direction_field_data()). A file is written under a
// temporary name and renamed when complete: a failure leaves no partial file.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PYTHON_FILES_H
#define SURFACE_MESH_DIRECTION_FIELDS_PYTHON_FILES_H

#include "python_face_field.h"

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/IO/direction_field_files.h>

#include "file_io/output_files.h"

#include <functional>
#include <vector>

namespace {

// An output that cannot be written (OSError in Python: thrown without the GIL,
// translated once it is held again).
struct File_error : std::runtime_error { using std::runtime_error::runtime_error; };

[[noreturn]] void refuse_file(const std::string& message) { throw File_error(message); }

// The field of `result` on the mesh of V and F, as the files need it.
SMDF::Direction_field_data field_data(const py::object& V, const py::object& F, const Result& result)
{
  Mesh mesh = make_mesh(real_array(V, "V", "an array of numbers of shape (number of vertices, 3)"),
                        integer_array(F, "F"));
  const auto d = result.directions.unchecked<2>();
  const auto m = result.magnitudes.unchecked<1>();
  const auto s = result.singular_faces.unchecked<2>();
  if(static_cast<std::size_t>(d.shape(0)) != mesh.number_of_vertices())
    refuse("the result was computed on another mesh (" + std::to_string(d.shape(0)) + " directions for " +
           std::to_string(mesh.number_of_vertices()) + " vertices)");
  std::vector<Kernel::Vector_3> directions;
  std::vector<double> magnitudes;
  for(py::ssize_t i = 0; i < d.shape(0); ++i)
  {
    directions.emplace_back(d(i, 0), d(i, 1), d(i, 2));
    magnitudes.push_back(m(i));
  }
  std::vector<std::pair<Face_index, int> > singular;
  for(py::ssize_t i = 0; i < s.shape(0); ++i)
  {
    if(s(i, 0) < 0 || static_cast<std::size_t>(s(i, 0)) >= mesh.number_of_faces())
      refuse("the result's singular faces are not faces of this mesh");
    singular.emplace_back(Face_index(static_cast<Mesh::size_type>(s(i, 0))), static_cast<int>(s(i, 1)));
  }
  return SMDF::make_direction_field_data(mesh, CGAL::make_property_map(directions), result.report, singular,
                                         CGAL::parameters::vertex_magnitude_map(CGAL::make_property_map(magnitudes)));
}

// The field on faces of `field` on the mesh of V and F (its rows are the
// data's triangles, so that the matching per row side carries over as it is).
SMDF::Direction_field_data face_field_data(const py::object& V, const py::object& F, const Face_field_result& field)
{
  const Index_array rows = integer_array(F, "F");
  const Mesh mesh = make_mesh(real_array(V, "V", "an array of numbers of shape (number of vertices, 3)"), rows);
  const auto d = field.face_directions.unchecked<2>();
  const auto s = field.singular_vertices.unchecked<2>();
  const auto j = field.matching.unchecked<2>();
  if(static_cast<std::size_t>(d.shape(0)) != mesh.number_of_faces())
    refuse("the field was computed on another mesh (" + std::to_string(d.shape(0)) + " directions for " +
           std::to_string(mesh.number_of_faces()) + " faces)");
  SMDF::Direction_field_data data;
  data.degree = field.report.degree;
  for(Vertex_index v : mesh.vertices()) data.points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
  const auto r = rows.unchecked<2>();
  for(py::ssize_t f = 0; f < d.shape(0); ++f)
  {
    data.faces.push_back({std::size_t(r(f, 0)), std::size_t(r(f, 1)), std::size_t(r(f, 2))});
    data.face_directions.push_back({d(f, 0), d(f, 1), d(f, 2)});
    data.face_matching.push_back({int(j(f, 0)), int(j(f, 1)), int(j(f, 2))});
  }
  for(py::ssize_t i = 0; i < s.shape(0); ++i)
  {
    if(s(i, 0) < 0 || static_cast<std::size_t>(s(i, 0)) >= mesh.number_of_vertices())
      refuse("the field's singular vertices are not vertices of this mesh");
    data.vertex_singularities.emplace_back(static_cast<std::size_t>(s(i, 0)), static_cast<int>(s(i, 1)));
  }
  return data;
}

// Writes through `write` as the program writes its outputs (output_files.h):
// a regular file under a unique temporary name renamed when complete (no
// partial file on any failure), a device or a pipe written directly, a
// symbolic link written through; the process's signal handlers untouched.
// `write` returns false when it wrote nothing that a reader could take back
// (a .vtu with no point): the file is then left out as the program leaves it
// out (output_files.h), and write_file() returns false.
bool write_file(const std::string& path, const std::function<bool(std::ostream&)>& write)
{
  if(path.empty()) refuse_file("the file name is empty");
  try
  {
    Output_files files(false);
    files.add("path", path, Input_files());
    const bool written = write(files.stream(path));
    if(!written) files.leave_out(path);
    files.commit();
    return written;
  }
  catch(const Output_error& e) { refuse_file(e.what()); }
}

// .vtu by the name (any case), as the program chooses
bool is_vtu(const std::string& path) { return soup_reading::lower_case_extension(path) == "vtu"; }

// vcglib (QuadWild) reads crosses only: as the program, other degrees are refused.
void crosses_only(const SMDF::Direction_field_data& d, const char* format)
{
  if(d.degree != 4)
    throw SMDF::Invalid_input_error(std::string(format) + " files hold cross fields (degree 4), not degree " +
                                    std::to_string(d.degree));
}

// A (rows, 3) array of vectors.
template <typename Vectors>
py::array_t<double> vector_rows(const Vectors& vectors)
{
  py::array_t<double> a({static_cast<py::ssize_t>(vectors.size()), py::ssize_t(3)});
  auto r = a.mutable_unchecked<2>();
  for(py::ssize_t i = 0; i < r.shape(0); ++i)
    for(int c = 0; c < 3; ++c) r(i, c) = vectors[static_cast<std::size_t>(i)][c];
  return a;
}

py::dict field_arrays(const py::object& V, const py::object& F, const Result& result)
{
  const SMDF::Direction_field_data data = field_data(V, F, result);
  const py::ssize_t n = data.degree;
  py::array_t<double> all({static_cast<py::ssize_t>(data.directions.size()), n, py::ssize_t(3)});
  auto a = all.mutable_unchecked<3>();
  for(py::ssize_t v = 0; v < a.shape(0); ++v)
    for(py::ssize_t k = 0; k < n; ++k)
      for(int c = 0; c < 3; ++c)
        a(v, k, c) = data.directions[static_cast<std::size_t>(v)][static_cast<std::size_t>(k)][c];
  py::dict arrays;
  arrays["normals"] = vector_rows(data.normals);
  arrays["directions"] = all;
  arrays["face_directions"] = vector_rows(SMDF::face_directions(data));
  return arrays;
}

typedef std::function<bool(std::ostream&, const SMDF::Direction_field_data&, const std::string&)> Writer;
typedef std::vector<std::pair<const char*, Writer> > Writers;

bool write_vtk(std::ostream& os, const SMDF::Direction_field_data& d, const std::string& path)
{
  if(is_vtu(path)) SMDF::IO::write_VTU(os, d); else SMDF::IO::write_VTK(os, d);
  return true;
}

bool write_vtk_singularities(std::ostream& os, const SMDF::Direction_field_data& d, const std::string& path)
{
  if(is_vtu(path) && d.singularities.empty() && d.vertex_singularities.empty())
    return false;  // meshio reads no .vtu without points
  if(is_vtu(path)) SMDF::IO::write_VTU_singularities(os, d); else SMDF::IO::write_VTK_singularities(os, d);
  return true;
}

bool write_rosy(std::ostream& os, const SMDF::Direction_field_data& d, const std::string&)
{
  crosses_only(d, "rosy");
  SMDF::IO::write_rosy(os, d);
  return true;
}

bool write_ffield(std::ostream& os, const SMDF::Direction_field_data& d, const std::string&)
{
  crosses_only(d, "ffield");
  SMDF::IO::write_ffield(os, d);
  return true;
}

// The writers of a field on vertices (of a Result).
Writers vertex_field_writers()
{
  return {{"write_vtk", write_vtk}, {"write_vtk_singularities", write_vtk_singularities},
          {"write_ply", [](std::ostream& os, const SMDF::Direction_field_data& d, const std::string&) {
             SMDF::IO::write_PLY(os, d);
             return true; }},
          {"write_rosy", write_rosy}, {"write_ffield", write_ffield},
          {"write_singularity_list", [](std::ostream& os, const SMDF::Direction_field_data& d, const std::string&) {
             SMDF::IO::write_singularities(os, d);
             return true; }}};
}

// The writers of a field on faces (of a FaceField): Directional's files, and
// those of both kinds.
Writers face_field_writers()
{
  return {{"write_rawfield", [](std::ostream& os, const SMDF::Direction_field_data& d, const std::string&) {
             SMDF::IO::write_rawfield(os, d);
             return true; }},
          {"write_sing", [](std::ostream& os, const SMDF::Direction_field_data& d, const std::string&) {
             SMDF::IO::write_vertex_singularities(os, d);
             return true; }},
          {"write_matching", [](std::ostream& os, const SMDF::Direction_field_data& d, const std::string&) {
             SMDF::IO::write_matching(os, d);
             return true; }},
          {"write_vtk", write_vtk}, {"write_vtk_singularities", write_vtk_singularities},
          {"write_rosy", write_rosy}, {"write_ffield", write_ffield}};
}

// Each writer as a function of (path, V, F, field): the field made into the
// data as `to_data` does, written without the GIL.
template <typename Field, typename ToData>
void bind_writers(py::module_& m, const Writers& writers, const ToData& to_data, const char* field_name,
                  const char* doc)
{
  for(const auto& w : writers)
  {
    const Writer writer = w.second;
    m.def(w.first, [writer, to_data](const py::object& path_object, const py::object& V, const py::object& F,
                                     const Field& field) {
            const std::string path = path_argument(path_object);
            const SMDF::Direction_field_data data = to_data(V, F, field);
            py::gil_scoped_release release;
            return write_file(path, [&](std::ostream& os) { return writer(os, data, path); });
          },
          py::arg("path"), py::arg("V"), py::arg("F"), py::arg(field_name), doc);
  }
}

void bind_files(py::module_& m)
{
  py::register_exception<File_error>(m, "FileError", PyExc_OSError);
  bind_writers<Result>(m, vertex_field_writers(), field_data, "result",
    "Writes the field of `result` (computed on V, F) as the command-line program's option of the same "
    "name does (write_vtk: .vtk or .vtu by the name). Returns True, or False when nothing was written "
    "(write_vtk_singularities to a .vtu for a field without singularities: meshio reads no .vtu without "
    "points; an older file of that name is removed). Raises OSError if the file cannot be written.");
  bind_writers<Face_field_result>(m, face_field_writers(), face_field_data, "field",
    "Writes the field on faces `field` (compute_face_directions() on V, F) as the command-line program's "
    "option of the same name does with --on faces (write_vtk: .vtk or .vtu by the name, the directions per "
    "face; write_rawfield, write_sing, write_matching: Directional's files). Returns True, or False when "
    "nothing was written (write_vtk_singularities to a .vtu for a field without singular vertices). Raises "
    "OSError if the file cannot be written.");
  for(const char* vertex_only : {"write_ply", "write_singularity_list"})
  {
    const std::string name = vertex_only;
    m.def(vertex_only, [name](const py::object&, const py::object&, const py::object&, const Face_field_result&) -> bool {
            refuse(name + " writes a field on vertices (a Result); a FaceField is written by write_vtk, "
                          "write_rosy, write_ffield, write_rawfield, write_sing and write_matching");
          },
          py::arg("path"), py::arg("V"), py::arg("F"), py::arg("field"));
  }
  m.def("field_arrays", &field_arrays, py::arg("V"), py::arg("F"), py::arg("result"),
        "The field of `result` (computed on V, F) as the files store it: a dict of 'normals' (|V|, 3), "
        "'directions' (|V|, n, 3): all n directions, the k-th the first turned by 2 pi k / n about the normal, "
        "and 'face_directions' (|F|, 3): one direction per face, as write_rosy writes them.");
}

}  // namespace

#endif
