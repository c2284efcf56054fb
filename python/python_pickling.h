// The state of the module's results for pickle and copy: each report of the
// C++ library as a tuple of its fields, in the order of its declaration
// (Direction_field_result.h), and back.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PYTHON_PICKLING_H
#define SURFACE_MESH_DIRECTION_FIELDS_PYTHON_PICKLING_H

#include "python_mesh.h"
#include "file_io/messages.h"

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

// An eigenvalue as Python shows it: nan where it was not computed (see `solves`).
inline double nan_if_absent(const std::optional<double>& value)
{
  return value.value_or(std::numeric_limits<double>::quiet_NaN());
}

inline std::optional<double> absent_if_nan(double value)
{
  if(std::isnan(value)) return std::nullopt;
  return value;
}

// Reads the fields of a tuple in order, with a clear error when the state is
// not one this module wrote.
class State_reader
{
  const py::tuple& m_state;
  std::size_t m_next = 0;

public:
  explicit State_reader(const py::tuple& state) : m_state(state) {}
  template <typename T>
  T next()
  {
    if(m_next >= m_state.size()) throw std::runtime_error("a pickled result of another version of the module");
    return m_state[m_next++].cast<T>();
  }
};

// An array as the results give it: read-only, so that changing one
// attribute's values cannot change another's (all_directions is made from
// directions and normals) or a copy's.
template <typename... Arrays>
void make_read_only(Arrays&... arrays)
{
  (arrays.attr("setflags")(py::arg("write") = false), ...);
}

// A restored state is checked as strictly as arrays from a user: each array
// has its number of dimensions and the extents given (-1: any), so that no
// method reads past an array that disagrees with the others.
inline void check_state_shape(const py::array& a, std::initializer_list<py::ssize_t> shape, const char* name)
{
  bool ok = a.ndim() == static_cast<py::ssize_t>(shape.size());
  py::ssize_t d = 0;
  for(py::ssize_t extent : shape)
  {
    if(ok && extent >= 0 && a.shape(d) != extent) ok = false;
    ++d;
  }
  if(!ok) refuse(std::string("the pickled state's ") + name + " does not have the shape of the result's other arrays");
}

inline void check_state_degree(int degree)
{
  if(degree < 1 || degree > SMDF::maximum_degree)
    refuse("the pickled state's degree " + std::to_string(degree) + " is not from 1 to " +
           std::to_string(SMDF::maximum_degree));
}

template <typename Report>
std::vector<std::string> solve_names(const Report& report)
{
  std::vector<std::string> names;
  for(const auto& c : report.components) names.push_back(solve_name(c.solve));
  return names;
}

py::tuple timings_state(const SMDF::Direction_field_timings& t)
{
  return py::make_tuple(t.setup_ms, t.factorization_ms, t.solve_ms, t.total_ms);
}

SMDF::Direction_field_timings timings_from(const py::tuple& state)
{
  State_reader r(state);
  SMDF::Direction_field_timings t;
  t.setup_ms = r.next<double>();
  t.factorization_ms = r.next<double>();
  t.solve_ms = r.next<double>();
  t.total_ms = r.next<double>();
  return t;
}

py::tuple component_state(const SMDF::Component_report& c)
{
  return py::make_tuple(c.number_of_vertices, c.number_of_faces, c.euler_characteristic, c.is_closed, nan_if_absent(c.eigenvalue),
                        c.lambda, c.alignment_weight, c.iterations, c.residual, c.converged, c.index_sum,
                        c.number_of_singular_faces, c.low_magnitude_fraction, static_cast<int>(c.solve));
}

SMDF::Field_solve solve_from(int value)
{
  if(value < 0 || value > static_cast<int>(SMDF::Field_solve::PARALLEL_SECTION))
    refuse("the pickled state's solve " + std::to_string(value) + " is not one of this module's");
  return static_cast<SMDF::Field_solve>(value);
}

SMDF::Component_report component_from(const py::tuple& state)
{
  State_reader r(state);
  SMDF::Component_report c;
  c.number_of_vertices = r.next<std::size_t>();
  c.number_of_faces = r.next<std::size_t>();
  c.euler_characteristic = r.next<int>();
  c.is_closed = r.next<bool>();
  c.eigenvalue = absent_if_nan(r.next<double>());
  c.lambda = r.next<double>();
  c.alignment_weight = r.next<double>();
  c.iterations = r.next<std::size_t>();
  c.residual = r.next<double>();
  c.converged = r.next<bool>();
  c.index_sum = r.next<int>();
  c.number_of_singular_faces = r.next<std::size_t>();
  c.low_magnitude_fraction = r.next<double>();
  c.solve = solve_from(r.next<int>());
  return c;
}

py::tuple report_state(const SMDF::Direction_field_result& report)
{
  py::list components;
  for(const auto& c : report.components) components.append(component_state(c));
  return py::make_tuple(report.degree, report.smoothness_parameter, components, report.number_of_isolated_vertices,
                        report.index_sum, report.number_of_singular_faces, report.iterations, report.residual,
                        report.converged, report.mollification, report.tangent_plane_vertices, report.prescribed,
                        report.holonomy_error, report.loop_turns, timings_state(report.timings));
}

SMDF::Direction_field_result report_from(const py::tuple& state)
{
  State_reader r(state);
  SMDF::Direction_field_result report;
  report.degree = r.next<int>();
  report.smoothness_parameter = r.next<double>();
  for(const auto& c : r.next<py::list>()) report.components.push_back(component_from(c.cast<py::tuple>()));
  report.number_of_isolated_vertices = r.next<std::size_t>();
  report.index_sum = r.next<long long>();
  report.number_of_singular_faces = r.next<std::size_t>();
  report.iterations = r.next<std::size_t>();
  report.residual = r.next<double>();
  report.converged = r.next<bool>();
  report.mollification = r.next<double>();
  report.tangent_plane_vertices = r.next<std::size_t>();
  report.prescribed = r.next<bool>();
  report.holonomy_error = r.next<double>();
  report.loop_turns = r.next<std::vector<std::pair<std::size_t, int> > >();
  report.timings = timings_from(r.next<py::tuple>());
  return report;
}

py::tuple face_component_state(const SMDF::Face_field_component_report& c)
{
  return py::make_tuple(c.number_of_vertices, c.number_of_faces, c.euler_characteristic, c.is_closed, nan_if_absent(c.eigenvalue),
                        c.lambda, c.alignment_weight, c.iterations, c.residual, c.converged, c.index_sum,
                        c.boundary_index, c.number_of_singular_vertices, static_cast<int>(c.solve));
}

SMDF::Face_field_component_report face_component_from(const py::tuple& state)
{
  State_reader r(state);
  SMDF::Face_field_component_report c;
  c.number_of_vertices = r.next<std::size_t>();
  c.number_of_faces = r.next<std::size_t>();
  c.euler_characteristic = r.next<int>();
  c.is_closed = r.next<bool>();
  c.eigenvalue = absent_if_nan(r.next<double>());
  c.lambda = r.next<double>();
  c.alignment_weight = r.next<double>();
  c.iterations = r.next<std::size_t>();
  c.residual = r.next<double>();
  c.converged = r.next<bool>();
  c.index_sum = r.next<long long>();
  c.boundary_index = r.next<long long>();
  c.number_of_singular_vertices = r.next<std::size_t>();
  c.solve = solve_from(r.next<int>());
  return c;
}

py::tuple face_report_state(const SMDF::Face_direction_field_result& report)
{
  py::list components;
  for(const auto& c : report.components) components.append(face_component_state(c));
  return py::make_tuple(report.degree, components, report.index_sum, report.number_of_singular_vertices,
                        report.iterations, report.residual, report.converged, report.mollification,
                        report.prescribed, report.number_of_non_principal_jumps, timings_state(report.timings),
                        report.number_of_cancelled_pairs, report.number_of_glued_edges);
}

SMDF::Face_direction_field_result face_report_from(const py::tuple& state)
{
  State_reader r(state);
  SMDF::Face_direction_field_result report;
  report.degree = r.next<int>();
  for(const auto& c : r.next<py::list>()) report.components.push_back(face_component_from(c.cast<py::tuple>()));
  report.index_sum = r.next<long long>();
  report.number_of_singular_vertices = r.next<std::size_t>();
  report.iterations = r.next<std::size_t>();
  report.residual = r.next<double>();
  report.converged = r.next<bool>();
  report.mollification = r.next<double>();
  report.prescribed = r.next<bool>();
  report.number_of_non_principal_jumps = r.next<std::size_t>();
  report.timings = timings_from(r.next<py::tuple>());
  report.number_of_cancelled_pairs = state.size() > 11 ? r.next<std::size_t>() : 0;  // earlier pickles: none
  report.number_of_glued_edges = state.size() > 12 ? r.next<std::size_t>() : 0;
  return report;
}

}  // namespace

#endif
