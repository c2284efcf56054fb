// compute_point_set_directions(): the field of a point set (C++
// compute_globally_optimal_point_set_directions()) as numpy arrays: a
// direction per point, the normals used, the triangles of the local
// triangulations with their holders, and the singular surface triangles.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PYTHON_POINT_SET_H
#define SURFACE_MESH_DIRECTION_FIELDS_PYTHON_POINT_SET_H

#include "python_options.h"
#include "python_pickling.h"
#include "file_io/optional_named_parameters.h"

#include <CGAL/Surface_mesh_direction_fields/globally_optimal_point_set_directions.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace {

struct Point_set_field
{
  py::array_t<double> directions, normals, magnitudes;
  py::array_t<long long> triangles, singular_triangles;
  py::array_t<unsigned char> holders;
  py::array_t<bool> on_surface;
  SMDF::Point_set_direction_field_result report;
  int degree = SMDF::default_degree;
};

struct Point_set_options
{
  int degree = SMDF::default_degree;
  double s = 0.;
  unsigned int neighbors = SMDF::default_number_of_neighbors;
  double tolerance = 1e-10;
  std::optional<double> lambda_t, alignment_weight;
  SMDF::Principal_curvature_alignment align = SMDF::Principal_curvature_alignment::NONE;
  bool eigenvalue_bound = false;
};

const char* const point_set_option_names[] = {"normals",  "degree",           "s",
                                              "neighbors", "tolerance",       "guidance",
                                              "align",    "lambda_t",         "alignment_weight",
                                              "eigenvalue_bound", "constraints"};

Point_set_options read_point_set_options(const py::dict& kw)
{
  for(const auto& item : kw)
  {
    const std::string key = py::cast<std::string>(item.first);
    if(std::find(std::begin(point_set_option_names), std::end(point_set_option_names), key) ==
       std::end(point_set_option_names))
      throw py::type_error("unexpected keyword argument '" + key + "'");
  }
  Point_set_options o;
  if(kw.contains("degree")) o.degree = degree_option(kw["degree"]);
  if(kw.contains("s")) o.s = option_as<double>(kw["s"], "s", "a number");
  if(kw.contains("neighbors")) o.neighbors = count_option(kw["neighbors"], "neighbors");
  if(kw.contains("tolerance")) o.tolerance = option_as<double>(kw["tolerance"], "tolerance", "a number");
  if(kw.contains("lambda_t") && !kw["lambda_t"].is_none())
    o.lambda_t = option_as<double>(kw["lambda_t"], "lambda_t", "a number");
  if(kw.contains("alignment_weight") && !kw["alignment_weight"].is_none())
    o.alignment_weight = option_as<double>(kw["alignment_weight"], "alignment_weight", "a number");
  o.align = align_option(kw);
  if(kw.contains("eigenvalue_bound"))
    o.eigenvalue_bound = option_as<bool>(kw["eigenvalue_bound"], "eigenvalue_bound", "True or False");
  return o;
}

std::vector<Kernel::Vector_3> vector_rows(const py::dict& kw, const char* name, std::size_t count)
{
  std::vector<Kernel::Vector_3> vectors;
  if(!kw.contains(name) || kw[name].is_none()) return vectors;
  const Float_array a = rows_of_three(kw[name], count, name);
  const auto r = a.unchecked<2>();
  for(py::ssize_t i = 0; i < a.shape(0); ++i) vectors.emplace_back(r(i, 0), r(i, 1), r(i, 2));
  return vectors;
}

// constraints = (point ids, directions k x 3), as flags and directions per point (empty: none)
struct Point_constraints
{
  std::vector<unsigned char> is_constrained;
  std::vector<Kernel::Vector_3> directions;
};

Point_constraints point_constraints(const py::dict& kw, std::size_t count)
{
  Point_constraints c;
  if(!kw.contains("constraints") || kw["constraints"].is_none()) return c;
  const Constraint_arrays given = constraint_arrays(kw["constraints"], "point");
  const Index_array& ids = given.ids;
  const auto id = ids.unchecked<1>();
  const auto dir = given.directions.unchecked<2>();
  c.is_constrained.assign(count, 0);
  c.directions.assign(count, CGAL::NULL_VECTOR);
  for(py::ssize_t i = 0; i < ids.shape(0); ++i)
  {
    if(id(i) < 0 || static_cast<std::size_t>(id(i)) >= count)
      refuse("constraints: point " + std::to_string(id(i)) + " is not a point of P");
    const std::size_t p = static_cast<std::size_t>(id(i));
    if(c.is_constrained[p]) refuse("constraints: point " + std::to_string(p) + " is listed twice");
    c.is_constrained[p] = 1;
    c.directions[p] = Kernel::Vector_3(dir(i, 0), dir(i, 1), dir(i, 2));
  }
  return c;
}

template <typename T>
py::array_t<T> rows_array(std::size_t rows, std::size_t columns)
{
  return columns == 1 ? py::array_t<T>({static_cast<py::ssize_t>(rows)})
                      : py::array_t<T>({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
}

void fill_point_set_arrays(const std::vector<Kernel::Vector_3>& directions, Point_set_field& r)
{
  const std::size_t np = directions.size(), nt = r.report.triangles.size();
  r.directions = rows_array<double>(np, 3);
  r.normals = rows_array<double>(np, 3);
  r.magnitudes = rows_array<double>(np, 1);
  r.triangles = rows_array<long long>(nt, 3);
  r.holders = rows_array<unsigned char>(nt, 1);
  r.on_surface = rows_array<bool>(nt, 1);
  r.singular_triangles = rows_array<long long>(r.report.singular_triangles.size(), 2);
  auto d = r.directions.mutable_unchecked<2>();
  auto n = r.normals.mutable_unchecked<2>();
  auto m = r.magnitudes.mutable_unchecked<1>();
  for(std::size_t i = 0; i < np; ++i)
  {
    for(int c = 0; c < 3; ++c)
    {
      d(py::ssize_t(i), c) = directions[i][c];
      n(py::ssize_t(i), c) = r.report.normals[i][c];
    }
    m(py::ssize_t(i)) = r.report.magnitudes[i];
  }
  auto t = r.triangles.mutable_unchecked<2>();
  auto h = r.holders.mutable_unchecked<1>();
  auto on = r.on_surface.mutable_unchecked<1>();
  for(std::size_t f = 0; f < nt; ++f)
  {
    for(int c = 0; c < 3; ++c) t(py::ssize_t(f), c) = static_cast<long long>(r.report.triangles[f][c]);
    h(py::ssize_t(f)) = r.report.holders[f];
    on(py::ssize_t(f)) = r.report.on_surface[f] != 0;
  }
  auto s = r.singular_triangles.mutable_unchecked<2>();
  for(std::size_t k = 0; k < r.report.singular_triangles.size(); ++k)
  {
    s(py::ssize_t(k), 0) = static_cast<long long>(r.report.singular_triangles[k].first);
    s(py::ssize_t(k), 1) = r.report.singular_triangles[k].second;
  }
  make_read_only(r.directions, r.normals, r.magnitudes, r.triangles, r.holders, r.on_surface, r.singular_triangles);
}

std::vector<Kernel::Point_3> point_rows(const py::object& P)
{
  const Float_array a = real_array(P, "P", "an array of numbers of shape (number of points, 3)");
  if(a.ndim() != 2 || a.shape(1) != 3) refuse("P must be an array of shape (number of points, 3)");
  const auto r = a.unchecked<2>();
  std::vector<Kernel::Point_3> points;
  for(py::ssize_t i = 0; i < a.shape(0); ++i) points.emplace_back(r(i, 0), r(i, 1), r(i, 2));
  return points;
}

Point_set_field compute_point_set_directions(const py::object& P, const py::kwargs& kw)
{
  const std::vector<Kernel::Point_3> points = point_rows(P);
  const Point_set_options o = read_point_set_options(kw);
  const std::vector<Kernel::Vector_3> normals = vector_rows(kw, "normals", points.size());
  const std::vector<Kernel::Vector_3> guidance = vector_rows(kw, "guidance", points.size());
  const Point_constraints constraints = point_constraints(kw, points.size());
  if((o.lambda_t || o.alignment_weight) && guidance.empty() && o.align == SMDF::Principal_curvature_alignment::NONE)
    refuse(std::string(o.lambda_t ? "lambda_t" : "alignment_weight") + " needs a guidance or align");
  if(o.lambda_t && o.alignment_weight) refuse("give either lambda_t or alignment_weight, not both");
  std::vector<std::size_t> ids(points.size());
  for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
  std::vector<Kernel::Vector_3> directions(points.size(), CGAL::NULL_VECTOR);
  Point_set_field r;
  r.degree = o.degree;
  {
    py::gil_scoped_release release;
    const auto np = CGAL::parameters::point_map(CGAL::make_property_map(points))
                      .degree(o.degree)
                      .smoothness_parameter(o.s)
                      .number_of_neighbors(o.neighbors)
                      .residual_tolerance(o.tolerance)
                      .principal_curvature_alignment(o.align)
                      .compute_eigenvalue_bound(o.eigenvalue_bound);
    optional_named_parameters::Given_options<optional_named_parameters::Not_offered,
                                             decltype(CGAL::make_property_map(guidance)),
                                             optional_named_parameters::Not_offered> given;
    if(!guidance.empty()) given.guidance = CGAL::make_property_map(guidance);
    given.alignment_weight = o.alignment_weight;
    given.alignment_lambda = o.lambda_t;
    const auto direction_map = CGAL::make_property_map(directions);
    auto compute = [&](const auto& with) {
      if(constraints.is_constrained.empty())
        return SMDF::compute_globally_optimal_point_set_directions(ids, direction_map, with);
      return SMDF::compute_globally_optimal_point_set_directions(
        ids, direction_map,
        with.point_is_constrained_map(CGAL::make_property_map(constraints.is_constrained))
          .point_constrained_direction_map(CGAL::make_property_map(constraints.directions)));
    };
    r.report = normals.empty()
                 ? optional_named_parameters::compute_with_point_guidance(given, np, compute)
                 : optional_named_parameters::compute_with_point_guidance(
                     given, np.normal_map(CGAL::make_property_map(normals)), compute);
  }
  fill_point_set_arrays(directions, r);
  return r;
}

const char* const point_set_doc =
  "compute_point_set_directions(P, /, *, normals=None, degree=4, s=0.0, neighbors=12, tolerance=1e-10,\n"
  "                             guidance=None, align=None, lambda_t=None, alignment_weight=None,\n"
  "                             eigenvalue_bound=False, constraints=None)\n\n"
  "The smoothest n-direction field of the points P (N, 3), without a mesh (user manual, 'Point Sets'): each\n"
  "point's `neighbors` nearest points are triangulated in its tangent plane (normals (N, 3) when given,\n"
  "estimated by jet fitting otherwise) and the mesh method runs on these local triangulations. With\n"
  "guidance (N, 3: a vector per point, its length its weight), the aligned field, as on a mesh (lambda_t or\n"
  "alignment_weight as in compute_directions); align='curvature' (or 'min-curvature', even degree) follows the\n"
  "principal curvatures of a quadric fitted to each point's 2 * neighbors nearest points; constraints=(ids,\n"
  "directions (k, 3)) fixes the directions of those points (hard constraints, as on a mesh). Returns a\n"
  "PointSetField: directions (N, 3; zero for a point in no triangle), normals, magnitudes (N,; 1 at the\n"
  "largest), triangles (T, 3) with holders (T,: how many of their points' triangulations hold them) and\n"
  "on_surface (T,: the triangles the singularities are read on), singular_triangles (k, 2: triangle, k; the\n"
  "index is k / n), and the report (index_sum, surface_euler_characteristic, surface_is_closed, eigenvalues).";

// The state for pickle and copy: the arrays, the degree, the report's flags
// and counts, its components and timings (the report's other vectors are the
// arrays).
py::tuple point_set_state(const Point_set_field& r)
{
  const SMDF::Point_set_direction_field_result& p = r.report;
  py::list components;
  for(const auto& c : p.components) components.append(component_state(c));
  return py::make_tuple(r.directions, r.normals, r.magnitudes, r.triangles, r.holders, r.on_surface,
                        r.singular_triangles, r.degree,
                        py::make_tuple(p.normals_estimated, p.number_of_points_without_triangles,
                                       p.surface_euler_characteristic, p.surface_is_closed, p.normals_ms),
                        components, timings_state(p.timings));
}

Point_set_field point_set_from(const py::tuple& state)
{
  State_reader read(state);
  Point_set_field r;
  r.directions = read.next<py::array_t<double> >();
  r.normals = read.next<py::array_t<double> >();
  r.magnitudes = read.next<py::array_t<double> >();
  r.triangles = read.next<py::array_t<long long> >();
  r.holders = read.next<py::array_t<unsigned char> >();
  r.on_surface = read.next<py::array_t<bool> >();
  r.singular_triangles = read.next<py::array_t<long long> >();
  r.degree = read.next<int>();
  check_state_degree(r.degree);
  const py::ssize_t np = r.directions.ndim() > 0 ? r.directions.shape(0) : -1;
  const py::ssize_t nt = r.triangles.ndim() > 0 ? r.triangles.shape(0) : -1;
  check_state_shape(r.directions, {np, 3}, "directions");
  check_state_shape(r.normals, {np, 3}, "normals");
  check_state_shape(r.magnitudes, {np}, "magnitudes");
  check_state_shape(r.triangles, {nt, 3}, "triangles");
  check_state_shape(r.holders, {nt}, "holders");
  check_state_shape(r.on_surface, {nt}, "on_surface");
  check_state_shape(r.singular_triangles, {-1, 2}, "singular_triangles");
  SMDF::Point_set_direction_field_result& p = r.report;
  State_reader flags(read.next<py::tuple>());
  p.normals_estimated = flags.next<bool>();
  p.number_of_points_without_triangles = flags.next<std::size_t>();
  p.surface_euler_characteristic = flags.next<int>();
  p.surface_is_closed = flags.next<bool>();
  p.normals_ms = flags.next<double>();
  for(const py::handle& c : read.next<py::list>()) p.components.push_back(component_from(c.cast<py::tuple>()));
  p.timings = timings_from(read.next<py::tuple>());
  const auto s = r.singular_triangles.unchecked<2>();
  for(py::ssize_t k = 0; k < s.shape(0); ++k)
  {
    if(s(k, 0) < 0 || s(k, 0) >= nt) refuse("the pickled state's singular_triangles are not among its triangles");
    p.singular_triangles.emplace_back(static_cast<std::size_t>(s(k, 0)), static_cast<int>(s(k, 1)));
  }
  make_read_only(r.directions, r.normals, r.magnitudes, r.triangles, r.holders, r.on_surface, r.singular_triangles);
  return r;
}

void bind_point_set_field(py::module_& m)
{
  py::class_<Point_set_field>(m, "PointSetField", "The field of a point set: read-only arrays and its report.")
    .def_readonly("directions", &Point_set_field::directions, "(N, 3) unit direction per point (zero: none)")
    .def_readonly("normals", &Point_set_field::normals, "(N, 3) the unit normals used")
    .def_readonly("magnitudes", &Point_set_field::magnitudes, "(N,) |u| relative to its largest")
    .def_readonly("triangles", &Point_set_field::triangles, "(T, 3) int64 triangles of the local triangulations")
    .def_readonly("holders", &Point_set_field::holders, "(T,) uint8: local triangulations holding each")
    .def_readonly("on_surface", &Point_set_field::on_surface, "(T,) bool: the surface triangles")
    .def_readonly("singular_triangles", &Point_set_field::singular_triangles, "(k, 2) int64: triangle, k")
    .def_readonly("degree", &Point_set_field::degree)
    .def_property_readonly("index_sum", [](const Point_set_field& r) {
      long long sum = 0;
      for(const auto& s : r.report.singular_triangles) sum += s.second;
      return sum;
    })
    .def_property_readonly("surface_euler_characteristic",
                           [](const Point_set_field& r) { return r.report.surface_euler_characteristic; })
    .def_property_readonly("surface_is_closed", [](const Point_set_field& r) { return r.report.surface_is_closed; })
    .def_property_readonly("normals_estimated", [](const Point_set_field& r) { return r.report.normals_estimated; })
    .def_property_readonly("points_without_triangles",
                           [](const Point_set_field& r) { return r.report.number_of_points_without_triangles; })
    .def_property_readonly("eigenvalues", [](const Point_set_field& r) {
      std::vector<double> values;
      for(const auto& c : r.report.components) values.push_back(nan_if_absent(c.eigenvalue));
      return values;
    })
    .def_property_readonly("converged", [](const Point_set_field& r) {
      bool all = true;
      for(const auto& c : r.report.components) all = all && c.converged;
      return all;
    })
    .def_property_readonly("alignment_weights", [](const Point_set_field& r) {
      std::vector<double> values;
      for(const auto& c : r.report.components) values.push_back(c.alignment_weight);
      return values;
    }, "per component, the alignment weight t = 1 / (1 + |u|_M) reached (0 without guidance)")
    .def(py::pickle(&point_set_state, &point_set_from))
    .def("__repr__", [](const Point_set_field& r) {
      return "<PointSetField n=" + std::to_string(r.degree) + ", " + std::to_string(r.directions.shape(0)) +
             " points, " + std::to_string(r.singular_triangles.shape(0)) + " singular triangles>";
    });
  m.def("compute_point_set_directions",
        [](const py::object& P, const py::kwargs& kw) { return compute_point_set_directions(P, kw); }, py::arg("P"),
        point_set_doc);
}

} // namespace

#endif // SURFACE_MESH_DIRECTION_FIELDS_PYTHON_POINT_SET_H
