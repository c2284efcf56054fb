// Python keyword arguments -> Options, and Options -> the named parameters
// of Globally_optimal_direction_field::compute() (the optional ones through
// file_io/optional_named_parameters.h, as the program passes them).
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PYTHON_OPTIONS_H
#define SURFACE_MESH_DIRECTION_FIELDS_PYTHON_OPTIONS_H

#include "python_mesh.h"

#include <CGAL/Surface_mesh_direction_fields/feature_edges.h>

#include "file_io/messages.h"
#include "file_io/optional_named_parameters.h"

#include <complex>
#include <initializer_list>
#include <limits>
#include <memory>
#include <string>

namespace {

// Every option of compute(), read from Python's keyword arguments.
struct Options
{
  int degree = CGAL::Surface_mesh_direction_fields::default_degree;
  double s = 0.;
  SMDF::Principal_curvature_alignment align = SMDF::Principal_curvature_alignment::NONE;
  SMDF::Principal_curvature_estimate curvature_estimate = SMDF::Principal_curvature_estimate::QUADRIC_FIT;
  SMDF::Boundary_alignment boundary = SMDF::Boundary_alignment::NONE;
  std::optional<double> lambda_t, alignment_weight;
  bool eigenvalue_bound = false;
  std::vector<Kernel::Vector_3> guidance;                  // empty: none
  std::vector<std::pair<Vertex_index, Kernel::Vector_3> > constraints;
  std::vector<Edge_index> features;                        // empty: none
  bool has_features = false;
  std::optional<double> feature_angle;
  unsigned int feature_cleanup = 4;  // detect_feature_edges()' feature_cleanup_steps
  std::optional<std::vector<std::pair<Face_index, int> > > prescribed;
  std::optional<std::vector<std::pair<std::size_t, int> > > loop_turns;
  double intrinsic_mollification = 1e-6;
  std::vector<Kernel::Vector_3> normals;  // per vertex (vertex_normal_map); empty: the angle-weighted ones
  py::object progress = py::none();  // None or a callable(fraction)
  unsigned int max_iterations = 1000;
  double tolerance = 1e-10;
  unsigned int seed = 0;
};

// A keyword argument of the type asked for, or a TypeError naming it.
template <typename T>
T option_as(const py::handle& value, const char* name, const char* what)
{
  try { return py::cast<T>(value); }
  catch(const py::cast_error&) { throw py::type_error(std::string(name) + " must be " + what); }
}

template <typename Enum>
Enum choose(const std::string& value, const char* option, std::initializer_list<std::pair<const char*, Enum> > names)
{
  std::string known;
  for(const auto& n : names)
  {
    if(value == n.first) return n.second;
    known += std::string(known.empty() ? "" : ", ") + "'" + n.first + "'";
  }
  refuse(std::string(option) + " must be one of " + known + " (got '" + value + "')");
}


// The property maps of one computation, on the module's own copy of the mesh.
struct Maps
{
  Mesh::Property_map<Vertex_index, Kernel::Vector_3> direction, guidance, constraint;
  Mesh::Property_map<Vertex_index, bool> constrained;
  Mesh::Property_map<Vertex_index, double> magnitude;
  Mesh::Property_map<Vertex_index, std::complex<double> > coefficient;
  Mesh::Property_map<Edge_index, bool> feature;
  Mesh::Property_map<Vertex_index, Kernel::Vector_3> normal;  // of the keyword normals

  // the outputs' maps; those of the options are added when an option first needs them
  explicit Maps(Mesh& mesh)
  {
    direction = mesh.add_property_map<Vertex_index, Kernel::Vector_3>("v:smdf_direction").first;
    magnitude = mesh.add_property_map<Vertex_index, double>("v:smdf_magnitude", 0.).first;
    coefficient = mesh.add_property_map<Vertex_index, std::complex<double> >("v:smdf_coefficient").first;
  }
};

// An array of real numbers as float64: integers and floats; complex numbers
// (numpy would drop the imaginary part), booleans and objects refused.
Float_array real_array(const py::handle& value, const char* name, const char* what)
{
  py::array a;
  try { a = py::module_::import("numpy").attr("asarray")(value); }
  catch(const py::error_already_set&) { throw py::type_error(std::string(name) + " must be " + what); }
  const char kind = a.dtype().kind();
  if(kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + " must be " + what + " (got an array of dtype " +
                         std::string(py::str(a.dtype())) + ")");
  return option_as<Float_array>(a, name, what);
}

Float_array rows_of_three(const py::object& value, std::size_t rows, const char* name)
{
  const Float_array a = real_array(value, name, "an array of numbers");
  if(a.ndim() != 2 || a.shape(1) != 3 || static_cast<std::size_t>(a.shape(0)) != rows)
    refuse(std::string(name) + " must be an array of shape (" + std::to_string(rows) + ", 3)");
  const auto r = a.unchecked<2>();
  for(py::ssize_t i = 0; i < a.shape(0); ++i)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(r(i, c))) refuse(std::string(name) + " row " + std::to_string(i) + " is not finite");
  return a;
}

// An array of integers (numpy integers, or floats that are whole numbers):
// 0.9 is refused, as the program refuses it, rather than truncated to 0.
Index_array integer_array(const py::object& value, const char* name)
{
  py::array a;
  try { a = py::module_::import("numpy").attr("asarray")(value); }
  catch(const py::error_already_set&) { throw py::type_error(std::string(name) + " must be an array of integers"); }
  const char kind = a.dtype().kind();
  if(kind == 'f')
  {
    const Float_array f = option_as<Float_array>(a, name, "an array of integers");
    const double* x = f.data();
    for(py::ssize_t i = 0; i < f.size(); ++i)
      if(!(std::isfinite(x[i]) && std::floor(x[i]) == x[i] && std::abs(x[i]) < 9.0e15))
        refuse(std::string(name) + " must hold integers, got " + compact(x[i]));
  }
  else if(kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + " must be an array of integers");
  else if(kind == 'u' && a.itemsize() == 8)  // 2^64 - 1 would become -1
  {
    const py::array_t<unsigned long long, py::array::c_style | py::array::forcecast> u(a);
    for(py::ssize_t i = 0; i < u.size(); ++i)
      if(u.data()[i] > static_cast<unsigned long long>((std::numeric_limits<long long>::max)()))
        refuse(std::string(name) + " must hold integers below 2^63, got " + std::to_string(u.data()[i]));
  }
  return option_as<Index_array>(a, name, "an array of integers");
}

Index_array index_rows(const py::object& value, py::ssize_t columns, const char* name)
{
  const Index_array a = integer_array(value, name);
  if(a.ndim() != 2 || a.shape(1) != columns)
    refuse(std::string(name) + " must be an array of shape (k, " + std::to_string(columns) + ")");
  return a;
}

// A count (iterations, seed): a Python integer in [0, 2^32 - 1], never wrapped.
unsigned int count_option(const py::handle& value, const char* name)
{
  const std::string what = std::string("an integer from 0 to 4294967295");
  if(!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
    throw py::type_error(std::string(name) + " must be " + what);
  const py::int_ i = py::reinterpret_borrow<py::int_>(value);
  if(i < py::int_(0) || i > py::int_(4294967295ULL)) refuse(std::string(name) + " must be " + what);
  return py::cast<unsigned int>(i);
}

// The degree n: a Python integer (not a bool) from 1 to maximum_degree.
int degree_option(const py::handle& value)
{
  const std::string what = "an integer from 1 to " + std::to_string(SMDF::maximum_degree);
  if(!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
    throw py::type_error("degree must be " + what);
  const py::int_ i = py::reinterpret_borrow<py::int_>(value);
  if(i < py::int_(1) || i > py::int_(SMDF::maximum_degree)) refuse("degree must be " + what);
  return py::cast<int>(i);
}

// constraints = (ids, directions k x 3) of vertices, faces or points (`element`), as checked arrays
struct Constraint_arrays
{
  Index_array ids;
  Float_array directions;
};

Constraint_arrays constraint_arrays(const py::object& value, const std::string& element)
{
  const std::string pair_of = "a pair (" + element + " ids, directions)";
  const py::tuple pair = option_as<py::tuple>(value, "constraints", pair_of.c_str());
  if(pair.size() != 2) refuse("constraints must be " + pair_of.substr(0, pair_of.size() - 1) + " of shape (k, 3))");
  Constraint_arrays c;
  c.ids = integer_array(pair[0], ("constraints' " + element + " ids").c_str());
  if(c.ids.ndim() != 1) refuse("constraints: the " + element + " ids must be a 1-dimensional array");
  c.directions = rows_of_three(pair[1], static_cast<std::size_t>(c.ids.shape(0)), "constraints' directions");
  return c;
}

// constraints = (vertex ids, directions k x 3)
void read_constraints(const py::object& value, const Mesh& mesh, Options& o)
{
  const Constraint_arrays c = constraint_arrays(value, "vertex");
  const Index_array& ids = c.ids;
  const auto id = ids.unchecked<1>();
  const auto dir = c.directions.unchecked<2>();
  std::vector<bool> listed(mesh.number_of_vertices(), false);
  for(py::ssize_t i = 0; i < ids.shape(0); ++i)
  {
    if(id(i) < 0 || static_cast<std::size_t>(id(i)) >= mesh.number_of_vertices())
      refuse("constraints: vertex " + std::to_string(id(i)) + " is not a vertex of the mesh");
    const Vertex_index v(static_cast<Mesh::size_type>(id(i)));
    if(listed[std::size_t(v)]) refuse("constraints: vertex " + std::to_string(id(i)) + " is listed twice");
    if(mesh.is_isolated(v))
      refuse("constraints: vertex " + std::to_string(id(i)) + " belongs to no face (it has no tangent plane)");
    listed[std::size_t(v)] = true;
    o.constraints.emplace_back(v, Kernel::Vector_3(dir(i, 0), dir(i, 1), dir(i, 2)));
  }
}

// feature_edges = E x 2 vertex pairs (each an edge of the mesh)
void read_feature_edges(const py::object& value, const Mesh& mesh, Options& o)
{
  const Index_array e = index_rows(value, 2, "feature_edges");
  const auto r = e.unchecked<2>();
  for(py::ssize_t i = 0; i < e.shape(0); ++i)
  {
    const long long a = r(i, 0), b = r(i, 1), n = static_cast<long long>(mesh.number_of_vertices());
    if(a < 0 || b < 0 || a >= n || b >= n) refuse("feature_edges row " + std::to_string(i) + ": no such vertex");
    const auto h = CGAL::halfedge(Vertex_index(static_cast<Mesh::size_type>(a)),
                                  Vertex_index(static_cast<Mesh::size_type>(b)), mesh);
    if(!h.second) refuse("feature_edges row " + std::to_string(i) + " is not an edge of the mesh");
    o.features.push_back(CGAL::edge(h.first, mesh));
  }
  o.has_features = true;
}

// prescribed = k x 2 (face, k): index k / n
void read_prescribed(const py::object& value, const Mesh& mesh, Options& o)
{
  const Index_array p = index_rows(value, 2, "prescribed");
  const auto r = p.unchecked<2>();
  std::vector<std::pair<Face_index, int> > faces;
  for(py::ssize_t i = 0; i < p.shape(0); ++i)
  {
    if(r(i, 0) < 0 || static_cast<std::size_t>(r(i, 0)) >= mesh.number_of_faces())
      refuse("prescribed row " + std::to_string(i) + ": face " + std::to_string(r(i, 0)) + " is not a face of the mesh");
    if(std::abs(r(i, 1)) > 1000000) refuse("prescribed row " + std::to_string(i) + ": k out of range");
    faces.emplace_back(Face_index(static_cast<Mesh::size_type>(r(i, 0))), static_cast<int>(r(i, 1)));
  }
  o.prescribed = std::move(faces);
}

// prescribed_loop_turns = m x 2 (loop, turns), as Result.loop_turns gives them
void read_loop_turns(const py::object& value, Options& o)
{
  const Index_array p = index_rows(value, 2, "prescribed_loop_turns");
  const auto r = p.unchecked<2>();
  std::vector<std::pair<std::size_t, int> > turns;
  for(py::ssize_t i = 0; i < p.shape(0); ++i)
  {
    if(r(i, 0) < 0) refuse("prescribed_loop_turns row " + std::to_string(i) + ": loop " + std::to_string(r(i, 0)) +
                           " is not a loop of the mesh");
    if(std::abs(r(i, 1)) > 1000000) refuse("prescribed_loop_turns row " + std::to_string(i) + ": turns out of range");
    turns.emplace_back(static_cast<std::size_t>(r(i, 0)), static_cast<int>(r(i, 1)));
  }
  o.loop_turns = std::move(turns);
}

// align= (meshes and point sets): none when absent or None.
SMDF::Principal_curvature_alignment align_option(const py::dict& kw)
{
  typedef SMDF::Principal_curvature_alignment A;
  if(!kw.contains("align") || kw["align"].is_none()) return A::NONE;
  return choose<A>(option_as<std::string>(kw["align"], "align", "a string"), "align",
                   {{"none", A::NONE}, {"curvature", A::MAXIMUM}, {"max-curvature", A::MAXIMUM},
                    {"min-curvature", A::MINIMUM}});
}

void read_enumerations(const py::dict& kw, Options& o)
{
  typedef SMDF::Principal_curvature_estimate E;
  typedef SMDF::Boundary_alignment B;
  o.align = align_option(kw);
  if(kw.contains("curvature_estimate"))
    o.curvature_estimate = choose<E>(option_as<std::string>(kw["curvature_estimate"], "curvature_estimate", "a string"), "curvature_estimate",
                                     {{"quadric-fit", E::QUADRIC_FIT}, {"hopf", E::HOPF_DIFFERENTIAL}});
  if(kw.contains("boundary") && !kw["boundary"].is_none())
    o.boundary = choose<B>(option_as<std::string>(kw["boundary"], "boundary", "a string"), "boundary",
                           {{"none", B::NONE}, {"tangent", B::TANGENT}, {"normal", B::NORMAL}});
}

const char* const option_names[] = {"degree", "s", "align", "curvature_estimate", "boundary", "guidance",
                                    "alignment_weight", "lambda_t", "eigenvalue_bound", "constraints",
                                    "feature_edges", "feature_angle", "feature_cleanup", "prescribed", "prescribed_loop_turns",
                                    "intrinsic_mollification", "normals", "max_iterations", "tolerance", "seed",
                                    "progress"};

// The keyword arguments of compute() (an unknown one is a TypeError, as Python's own).
Options read_options(const py::dict& kw, Mesh& mesh)
{
  for(const auto& item : kw)
  {
    const std::string key = py::cast<std::string>(item.first);
    if(std::find(std::begin(option_names), std::end(option_names), key) == std::end(option_names))
      throw py::type_error("unexpected keyword argument '" + key + "'");
  }
  Options o;
  if(kw.contains("degree")) o.degree = degree_option(kw["degree"]);
  if(kw.contains("s")) o.s = option_as<double>(kw["s"], "s", "a number");
  read_enumerations(kw, o);
  auto given = [&](const char* key) { return kw.contains(key) && !kw[key].is_none(); };
  if(given("lambda_t")) o.lambda_t = option_as<double>(kw["lambda_t"], "lambda_t", "a number");
  if(given("alignment_weight")) o.alignment_weight = option_as<double>(kw["alignment_weight"], "alignment_weight", "a number");
  if(kw.contains("eigenvalue_bound")) o.eigenvalue_bound = option_as<bool>(kw["eigenvalue_bound"], "eigenvalue_bound", "True or False");
  if(given("guidance"))
  {
    const Float_array g = rows_of_three(kw["guidance"], mesh.number_of_vertices(), "guidance");
    const auto r = g.unchecked<2>();
    for(py::ssize_t i = 0; i < g.shape(0); ++i) o.guidance.emplace_back(r(i, 0), r(i, 1), r(i, 2));
  }
  if(given("constraints")) read_constraints(kw["constraints"], mesh, o);
  if(given("feature_edges")) read_feature_edges(kw["feature_edges"], mesh, o);
  if(given("feature_angle"))
  {
    const double angle = option_as<double>(kw["feature_angle"], "feature_angle", "a number");
    if(!(angle > 0. && angle < 180.)) refuse("feature_angle must lie in (0, 180) degrees");
    o.feature_angle = angle;
  }
  if(kw.contains("feature_cleanup"))
  {
    o.feature_cleanup = count_option(kw["feature_cleanup"], "feature_cleanup");
    if(o.feature_cleanup > 1000) refuse("feature_cleanup must be from 0 to 1000");
  }
  if(given("prescribed")) read_prescribed(kw["prescribed"], mesh, o);
  if(given("prescribed_loop_turns"))
  {
    if(!o.prescribed) refuse("prescribed_loop_turns applies with prescribed only (the smoothest and aligned fields "
                             "choose their own turns)");
    read_loop_turns(kw["prescribed_loop_turns"], o);
  }
  if(kw.contains("intrinsic_mollification"))
    o.intrinsic_mollification = option_as<double>(kw["intrinsic_mollification"], "intrinsic_mollification", "a number");
  if(given("normals"))
  {
    const Float_array n = rows_of_three(kw["normals"], mesh.number_of_vertices(), "normals");
    const auto r = n.unchecked<2>();
    for(py::ssize_t i = 0; i < n.shape(0); ++i)
    {
      o.normals.emplace_back(r(i, 0), r(i, 1), r(i, 2));
      if(o.normals.back() == CGAL::NULL_VECTOR) refuse("normals row " + std::to_string(i) + " is zero");
    }
  }
  if(given("progress"))
  {
    if(!PyCallable_Check(kw["progress"].ptr())) throw py::type_error("progress must be a callable(fraction) or None");
    o.progress = kw["progress"];
  }
  if(kw.contains("max_iterations")) o.max_iterations = count_option(kw["max_iterations"], "max_iterations");
  if(kw.contains("tolerance")) o.tolerance = option_as<double>(kw["tolerance"], "tolerance", "a number");
  if(kw.contains("seed")) o.seed = count_option(kw["seed"], "seed");
  if((o.lambda_t || o.alignment_weight) && o.align == SMDF::Principal_curvature_alignment::NONE && o.guidance.empty())
    refuse(std::string(o.lambda_t ? "lambda_t" : "alignment_weight") +
           " needs something to align to (align or guidance)");
  if(o.prescribed && (o.lambda_t || o.alignment_weight || o.eigenvalue_bound))
    refuse("prescribed singularities take no lambda_t, alignment_weight or eigenvalue_bound");
  if(o.lambda_t && o.alignment_weight) refuse("give either lambda_t or alignment_weight, not both");
  return o;
}

// The maps take the options' values (the mesh's own maps, reset at every call).
void fill_maps(const Options& o, Mesh& mesh, Maps& maps)
{
  if(!o.normals.empty())
  {
    maps.normal = mesh.add_property_map<Vertex_index, Kernel::Vector_3>("v:smdf_normal").first;
    for(Vertex_index v : mesh.vertices()) put(maps.normal, v, o.normals[static_cast<std::size_t>(v)]);
  }
  if(!o.guidance.empty())
  {
    maps.guidance = mesh.add_property_map<Vertex_index, Kernel::Vector_3>("v:smdf_guidance").first;
    for(Vertex_index v : mesh.vertices()) put(maps.guidance, v, o.guidance[static_cast<std::size_t>(v)]);
  }
  if(!o.constraints.empty())
  {
    maps.constrained = mesh.add_property_map<Vertex_index, bool>("v:smdf_constrained", false).first;
    maps.constraint = mesh.add_property_map<Vertex_index, Kernel::Vector_3>("v:smdf_constraint").first;
    for(Vertex_index v : mesh.vertices()) put(maps.constrained, v, false);
    for(const auto& c : o.constraints)
    {
      put(maps.constrained, c.first, true);
      put(maps.constraint, c.first, c.second);
    }
  }
  if(o.has_features || o.feature_angle)
  {
    maps.feature = mesh.add_property_map<Edge_index, bool>("e:smdf_feature", false).first;
    for(Edge_index e : mesh.edges()) put(maps.feature, e, false);
    for(Edge_index e : o.features) put(maps.feature, e, true);
    if(o.feature_angle)
      SMDF::detect_feature_edges(mesh, *o.feature_angle, maps.feature,
                                 CGAL::parameters::feature_cleanup_steps(o.feature_cleanup));
  }
}

// The C++ side's progress_callback for one computation, called on the
// computing thread without the GIL: it takes the GIL, runs Python's signal
// handlers (Ctrl-C raises KeyboardInterrupt there) and the user's progress
// callable; an exception from either stops the computation and is kept, to
// be raised once the call has unwound (see `raise_if_stopped()`).
class Python_progress
{
public:
  explicit Python_progress(const py::object& user) : m_user(user) {}

  bool operator()(double fraction)
  {
    py::gil_scoped_acquire gil;
    try
    {
      if(PyErr_CheckSignals() != 0) throw py::error_already_set();
      if(!m_user.is_none()) m_user(fraction);
      return true;
    }
    catch(py::error_already_set& e)
    {
      m_error = std::make_unique<py::error_already_set>(std::move(e));
      return false;
    }
  }

  // Ctrl-C after the last fraction: checked before the result's arrays are
  // made (without the GIL; the user's callable is not called again)
  void stop_if_signalled()
  {
    {
      py::gil_scoped_acquire gil;
      if(PyErr_CheckSignals() == 0) return;
      m_error = std::make_unique<py::error_already_set>();
    }
    throw SMDF::Computation_interrupted("interrupted before the result was made");
  }

  // with the GIL held: the Python exception that stopped the computation
  void raise_if_stopped()
  {
    if(m_error) throw py::error_already_set(std::move(*m_error));
  }

private:
  py::object m_user;
  std::unique_ptr<py::error_already_set> m_error;
};

// compute() with the named parameters of the options; `call(np)` computes
// the field (the class's compute() or the free function).
template <typename Call, typename Out>
SMDF::Direction_field_result compute_field(const Call& call, const Options& o, const Maps& maps, Out singularities,
                                           Python_progress& progress)
{
  const auto np = CGAL::parameters::degree(o.degree)
                    .smoothness_parameter(o.s)
                    .principal_curvature_alignment(o.align)
                    .principal_curvature_estimate(o.curvature_estimate)
                    .boundary_alignment(o.boundary)
                    .compute_eigenvalue_bound(o.eigenvalue_bound)
                    .number_of_iterations(o.max_iterations)
                    .residual_tolerance(o.tolerance)
                    .random_seed(o.seed)
                    .intrinsic_mollification(o.intrinsic_mollification)
                    .progress_callback([&progress](double fraction) { return progress(fraction); })
                    .vertex_magnitude_map(maps.magnitude)
                    .vertex_coefficient_map(maps.coefficient)
                    .singularities_output_iterator(singularities);
  typedef Mesh::Property_map<Vertex_index, Kernel::Vector_3> Vector_map;
  typedef Mesh::Property_map<Vertex_index, bool> Bool_map;
  optional_named_parameters::Given_options<Face_index, Vector_map, Mesh::Property_map<Edge_index, bool>,
                                           std::pair<Bool_map, Vector_map> > given;
  given.alignment_weight = o.alignment_weight;
  given.alignment_lambda = o.lambda_t;
  if(!o.guidance.empty()) given.guidance = maps.guidance;
  if(!o.constraints.empty()) given.constraints = std::make_pair(maps.constrained, maps.constraint);
  if(o.has_features || o.feature_angle) given.features = maps.feature;
  if(o.prescribed) given.prescribed = &*o.prescribed;
  if(o.loop_turns) given.loop_turns = &*o.loop_turns;
  return optional_named_parameters::compute_with(given, np, call);
}

}  // namespace

#endif
