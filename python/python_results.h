// The module's classes: Result (numpy arrays and the report of one field),
// DirectionField (the C++ class: the mesh work and factorizations kept for
// repeated calls), compute_globally_optimal_directions() and read_mesh().
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PYTHON_RESULTS_H
#define SURFACE_MESH_DIRECTION_FIELDS_PYTHON_RESULTS_H

#include "python_options.h"
#include "python_pickling.h"

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>

#include <atomic>
#include <cerrno>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

typedef Eigen::SparseMatrix<std::complex<double> > Complex_matrix;

struct Result
{
  py::array_t<double> directions, magnitudes, normals, tangent_frames;
  py::array_t<std::complex<double> > coefficients;
  py::array_t<long long> singular_faces, loop_turns;
  std::vector<double> eigenvalues;
  SMDF::Direction_field_result report;
};

// The values of one computed field, copied from the mesh's maps while the
// object's lock is held (no GIL needed): a later call on the same object
// cannot overwrite them before they become arrays.
struct Field_values
{
  std::vector<double> directions, magnitudes, normals, frames;  // 3, 1, 3 and 6 per vertex
  std::vector<std::complex<double> > coefficients;
  std::vector<std::pair<Face_index, int> > singular;
  SMDF::Direction_field_result report;
};

// The unit tangent vector along v's reference edge (user manual,
// "Conventions"): on the boundary the boundary edge with the surface on its
// left, inside the edge to the neighbour of smallest index; zero for an
// isolated vertex.
SMDF::internal::Vec3 reference_edge(const Mesh& mesh, const std::vector<SMDF::internal::Vec3>& points, Vertex_index v,
                                    const SMDF::internal::Vec3& normal)
{
  using SMDF::internal::Vec3;
  using SMDF::internal::operator*;
  using SMDF::internal::operator-;
  const Mesh::Halfedge_index incoming = mesh.halfedge(v);
  if(incoming == Mesh::null_halfedge()) return Vec3{0., 0., 0.};
  // a border vertex's halfedge is a border one (Surface_mesh keeps it so)
  Vertex_index w = mesh.source(incoming);
  if(!mesh.is_border(incoming))
    for(auto h : CGAL::halfedges_around_target(incoming, mesh)) w = (std::min)(w, mesh.source(h));
  Vec3 r = points[std::size_t(w)] - points[std::size_t(v)];
  const double largest = (std::max)({std::abs(r[0]), std::abs(r[1]), std::abs(r[2])});
  if(largest > 0. && std::isfinite(largest)) r = (1. / largest) * r;  // no overflow in the squares
  return SMDF::internal::normalized(r - SMDF::internal::dot(r, normal) * normal);
}

// The normals the directions turn about (made orthogonal to each direction,
// as make_direction_field_data() makes them for the files) and each vertex's
// tangent frame: e1 along the reference edge, e2 = normal x e1.
void copy_normals_and_frames(const Mesh& mesh, const Maps& maps, bool user_normals, Field_values& values)
{
  using SMDF::internal::Vec3;
  using SMDF::internal::operator*;
  using SMDF::internal::operator-;
  // in parallel, as the engine's passes: Surface_mesh's indices are 0 to n - 1 (no removed element)
  std::vector<Vec3> points(mesh.number_of_vertices()), normals;
  SMDF::internal::parallel_for_each_index(points.size(), [&](std::size_t i) {
    const Kernel::Point_3& p = mesh.point(Vertex_index(static_cast<Mesh::size_type>(i)));
    points[i] = {p.x(), p.y(), p.z()};
  });
  if(user_normals)
    for(Vertex_index v : mesh.vertices())
    {
      const Kernel::Vector_3 n = get(maps.normal, v);
      normals.push_back({n.x(), n.y(), n.z()});
    }
  else
  {
    std::vector<std::array<std::size_t, 3> > faces(mesh.number_of_faces());
    SMDF::internal::parallel_for_each_index(faces.size(), [&](std::size_t f) {
      const Mesh::Halfedge_index h = mesh.halfedge(Face_index(static_cast<Mesh::size_type>(f)));
      // in the order of vertices_around_face(), as make_direction_field_data() lists them: the same sums
      faces[f] = {std::size_t(mesh.target(h)), std::size_t(mesh.target(mesh.next(h))), std::size_t(mesh.source(h))};
    });
    normals = SMDF::internal::angle_weighted_normals(points, faces);
  }
  values.normals.resize(3 * points.size());
  values.frames.resize(6 * points.size());
  SMDF::internal::parallel_for_each_index(points.size(), [&](std::size_t i) {
    const Vec3 d{values.directions[3 * i], values.directions[3 * i + 1], values.directions[3 * i + 2]};
    const Vec3 normal = SMDF::internal::normalized(normals[i] - SMDF::internal::dot(normals[i], d) * d);
    const Vec3 e1 = reference_edge(mesh, points, Vertex_index(static_cast<Mesh::size_type>(i)), normal);
    const Vec3 e2 = SMDF::internal::cross(normal, e1);
    std::copy(normal.begin(), normal.end(), values.normals.begin() + static_cast<std::ptrdiff_t>(3 * i));
    std::copy(e1.begin(), e1.end(), values.frames.begin() + static_cast<std::ptrdiff_t>(6 * i));
    std::copy(e2.begin(), e2.end(), values.frames.begin() + static_cast<std::ptrdiff_t>(6 * i + 3));
  });
}

Field_values copy_field(const Mesh& mesh, const Maps& maps, bool user_normals)
{
  Field_values values;
  values.directions.reserve(3 * mesh.number_of_vertices());
  values.magnitudes.reserve(mesh.number_of_vertices());
  for(Vertex_index v : mesh.vertices())
  {
    const Kernel::Vector_3 x = get(maps.direction, v);
    values.directions.insert(values.directions.end(), {x.x(), x.y(), x.z()});
    values.magnitudes.push_back(get(maps.magnitude, v));
    values.coefficients.push_back(get(maps.coefficient, v));
  }
  copy_normals_and_frames(mesh, maps, user_normals, values);
  return values;
}

Result with_read_only_arrays(Result r)
{
  make_read_only(r.directions, r.magnitudes, r.coefficients, r.normals, r.tangent_frames, r.singular_faces,
                 r.loop_turns);
  return r;
}

// The arrays of one computed field (with the GIL held).
Result make_result(Field_values values)
{
  Result r;
  const py::ssize_t nv = static_cast<py::ssize_t>(values.magnitudes.size());
  r.directions = py::array_t<double>({nv, py::ssize_t(3)});
  r.magnitudes = py::array_t<double>(nv);
  std::copy(values.directions.begin(), values.directions.end(), r.directions.mutable_data());
  std::copy(values.magnitudes.begin(), values.magnitudes.end(), r.magnitudes.mutable_data());
  r.coefficients = py::array_t<std::complex<double> >(nv);
  std::copy(values.coefficients.begin(), values.coefficients.end(), r.coefficients.mutable_data());
  r.normals = py::array_t<double>({nv, py::ssize_t(3)});
  r.tangent_frames = py::array_t<double>({nv, py::ssize_t(2), py::ssize_t(3)});
  std::copy(values.normals.begin(), values.normals.end(), r.normals.mutable_data());
  std::copy(values.frames.begin(), values.frames.end(), r.tangent_frames.mutable_data());
  const auto& singular = values.singular;
  r.singular_faces = py::array_t<long long>({static_cast<py::ssize_t>(singular.size()), py::ssize_t(2)});
  auto s = r.singular_faces.mutable_unchecked<2>();
  for(std::size_t i = 0; i < singular.size(); ++i)
  {
    s(static_cast<py::ssize_t>(i), 0) = static_cast<long long>(singular[i].first);
    s(static_cast<py::ssize_t>(i), 1) = singular[i].second;
  }
  const auto& turns = values.report.loop_turns;
  r.loop_turns = py::array_t<long long>({static_cast<py::ssize_t>(turns.size()), py::ssize_t(2)});
  auto t = r.loop_turns.mutable_unchecked<2>();
  for(std::size_t i = 0; i < turns.size(); ++i)
  {
    t(static_cast<py::ssize_t>(i), 0) = static_cast<long long>(turns[i].first);
    t(static_cast<py::ssize_t>(i), 1) = turns[i].second;
  }
  for(const auto& c : values.report.components) r.eigenvalues.push_back(nan_if_absent(c.eigenvalue));
  r.report = std::move(values.report);
  return with_read_only_arrays(std::move(r));
}

// A message of the C++ library with its named parameters called by the
// keywords a Python user wrote.
std::string in_python_names(std::string message)
{
  static const std::pair<const char*, const char*> names[] = {
    {"vertex_guidance_map", "guidance"}, {"alignment_lambda", "lambda_t"},
    {"prescribed_singularities", "prescribed"}, {"vertex_is_constrained_map", "constraints"},
    {"vertex_constrained_direction_map", "constraints"}, {"edge_is_feature_map", "feature_edges"},
    {"smoothness_parameter", "s"}, {"number_of_iterations", "max_iterations"},
    {"residual_tolerance", "tolerance"}, {"random_seed", "seed"}, {"principal_curvature_alignment", "align"},
    {"principal_curvature_estimate", "curvature_estimate"}, {"boundary_alignment", "boundary"},
    {"compute_eigenvalue_bound", "eigenvalue_bound"}};
  for(const auto& name : names)
    for(std::size_t at = message.find(name.first); at != std::string::npos;
        at = message.find(name.first, at + std::strlen(name.second)))
      message.replace(at, std::strlen(name.first), name.second);
  return message;
}

// A component's eigen-solve stopped at max_iterations above its tolerance:
// a RuntimeWarning (an exception where warnings are errors).
void warn_not_converged(const SMDF::Direction_field_result& report)
{
  const std::string text = "the eigen-solve did not converge in " + std::to_string(report.iterations) +
                           " iterations (relative residual " + compact(report.residual) +
                           "); raise max_iterations or tolerance";
  // at the caller's line: level 1 is the package's Python wrapper that called the module
  if(PyErr_WarnEx(PyExc_RuntimeWarning, text.c_str(), 2) != 0) throw py::error_already_set();
}

// One call at a time on an object. A call from the thread that holds it
// (the object's own progress callback calling back into it) is an error: it
// would wait for itself.
class Busy_lock
{
  std::mutex m_mutex;
  std::atomic<std::thread::id> m_holder{};

public:
  class Guard
  {
    Busy_lock& m_lock;

  public:
    explicit Guard(Busy_lock& lock) : m_lock(lock)
    {
      if(m_lock.m_holder.load() == std::this_thread::get_id())
        throw std::runtime_error("this DirectionField is busy with a call that has not returned (a progress "
                                 "callback cannot call back into the object it reports on)");
      m_lock.m_mutex.lock();
      m_lock.m_holder.store(std::this_thread::get_id());
    }
    ~Guard()
    {
      m_lock.m_holder.store(std::thread::id());
      m_lock.m_mutex.unlock();
    }
    Guard(const Guard&) = delete;
    Guard& operator=(const Guard&) = delete;
  };
};

// The module's object: its own copy of the mesh (with the maps of the
// options) and, once compute() is called, the C++ class over it.
class Direction_field_object
{
public:
  Direction_field_object(const py::object& V, const py::object& F)
    : m_mesh(make_mesh(real_array(V, "V", "an array of numbers of shape (number of vertices, 3)"),
                       integer_array(F, "F"))),
      m_maps(m_mesh)
  {}

  // `as_free_function`: through the C++ free function (bit for bit what C++
  // users and the program get; its single call assembles an aligned system
  // directly, which can change the last digit against the class), else
  // through the class, kept for the next call
  Result compute(const py::kwargs& kwargs, bool as_free_function = false)
  {
    const Options o = read_options(kwargs, m_mesh);
    Python_progress progress(o.progress);
    std::vector<std::pair<Face_index, int> > singular;
    SMDF::Direction_field_result report;
    Field_values values;
    try
    {
      // the computation runs without the GIL: other Python threads go on (one object, one call at a time)
      py::gil_scoped_release release;
      Busy_lock::Guard lock(m_busy);
      fill_maps(o, m_mesh, m_maps);
      if(as_free_function && o.normals.empty())
        report = compute_field([&](const auto& np) {
          return SMDF::compute_globally_optimal_directions(m_mesh, m_maps.direction, np);
        }, o, m_maps, std::back_inserter(singular), progress);
      else
      {
        // the class's construction takes the mesh options (a free function call with normals: the class once)
        if(!m_field || o.intrinsic_mollification != m_mollification || o.normals != m_normals) make_field(o);
        report = compute_field([&](const auto& np) { return m_field->compute(m_maps.direction, np); }, o, m_maps,
                               std::back_inserter(singular), progress);
        if(as_free_function) m_field.reset();
      }
      progress.stop_if_signalled();
      values = copy_field(m_mesh, m_maps, !o.normals.empty());  // still under the lock: the maps are this call's
    }
    catch(const SMDF::Invalid_input_error& e)
    {
      throw SMDF::Invalid_input_error(in_python_names(e.what()));
    }
    catch(const SMDF::Computation_interrupted&)
    {
      progress.raise_if_stopped();  // KeyboardInterrupt, or what the progress callable raised
      throw;
    }
    values.singular = std::move(singular);
    values.report = std::move(report);
    if(!values.report.converged) warn_not_converged(values.report);
    return make_result(std::move(values));
  }

  // pybind11 takes the storage of an object made by __new__ alone (whose
  // __init__ never ran) from this operator new when a method is called on it:
  // zeroed, so that such an object is recognized by its signature (below)
  // instead of read as garbage.
  static void* operator new(std::size_t size)
  {
    void* p = ::operator new(size);
    std::memset(p, 0, size);
    return p;
  }
  static void operator delete(void* p) { ::operator delete(p); }

  // A and M of (n, s) on this mesh (Globally_optimal_direction_field::energy_and_mass_matrices()).
  std::pair<Complex_matrix, Complex_matrix> matrices(int degree, double s, double mollification)
  {
    try
    {
      py::gil_scoped_release release;
      Busy_lock::Guard lock(m_busy);
      if(!m_field || mollification != m_mollification)
      {
        Options o;  // the normals do not enter A and M
        o.intrinsic_mollification = mollification;
        make_field(o);
      }
      return m_field->energy_and_mass_matrices(degree, s);
    }
    catch(const SMDF::Invalid_input_error& e)
    {
      throw SMDF::Invalid_input_error(in_python_names(e.what()));
    }
  }

  bool constructed() const { return m_signature == constructed_signature; }
  std::size_t vertices() const { return m_mesh.number_of_vertices(); }
  std::size_t faces() const { return m_mesh.number_of_faces(); }

  double construction_ms()
  {
    py::gil_scoped_release release;  // a compute() of another thread may hold the lock
    Busy_lock::Guard lock(m_busy);
    return m_field ? m_field->construction_ms() : 0.;
  }

private:
  // The C++ class over the mesh with the options of its construction (the
  // mesh work is redone when they change).
  void make_field(const Options& o)
  {
    m_field.reset();
    const auto np = CGAL::parameters::intrinsic_mollification(o.intrinsic_mollification);
    if(o.normals.empty()) m_field = std::make_unique<Field>(m_mesh, np);
    else m_field = std::make_unique<Field>(m_mesh, np.vertex_normal_map(m_maps.normal));
    m_mollification = o.intrinsic_mollification;
    m_normals = o.normals;
  }

  static constexpr std::uint64_t constructed_signature = 0x534d44465f6f626aULL;
  std::uint64_t m_signature = constructed_signature;
  Mesh m_mesh;
  Maps m_maps;
  std::unique_ptr<Field> m_field;
  double m_mollification = 1e-6;           // of m_field's construction
  std::vector<Kernel::Vector_3> m_normals;  // of m_field's construction (empty: the angle-weighted ones)
  Busy_lock m_busy;
};

py::dict timings_of(const SMDF::Direction_field_result& r)
{
  py::dict t;
  t["setup_ms"] = r.timings.setup_ms;
  t["factorization_ms"] = r.timings.factorization_ms;
  t["solve_ms"] = r.timings.solve_ms;
  t["total_ms"] = r.timings.total_ms;
  return t;
}

// All n directions of every vertex, as the files show them (the first turned
// about the normal by the rotation of make_direction_field_data()).
py::array_t<double> all_directions(const Result& r)
{
  const py::ssize_t nv = r.directions.shape(0), n = r.report.degree;
  py::array_t<double> all({nv, n, py::ssize_t(3)});
  auto a = all.mutable_unchecked<3>();
  const auto d = r.directions.unchecked<2>();
  const auto normal = r.normals.unchecked<2>();
  for(py::ssize_t v = 0; v < nv; ++v)
    for(py::ssize_t k = 0; k < n; ++k)
    {
      const SMDF::internal::Vec3 turned = SMDF::internal::rotated(
        {d(v, 0), d(v, 1), d(v, 2)}, {normal(v, 0), normal(v, 1), normal(v, 2)},
        2. * CGAL_PI * static_cast<double>(k) / static_cast<double>(n));
      for(int c = 0; c < 3; ++c) a(v, k, c) = turned[static_cast<std::size_t>(c)];
    }
  return all;
}

// A compressed-column matrix as the arrays scipy.sparse.csc_matrix takes:
// (data, indices, indptr), and its number of rows.
py::tuple compressed_columns(Complex_matrix matrix)
{
  matrix.makeCompressed();
  const Complex_matrix::StorageIndex columns = static_cast<Complex_matrix::StorageIndex>(matrix.cols());
  const Complex_matrix::StorageIndex entries = matrix.outerIndexPtr()[columns];
  py::array_t<std::complex<double> > data(entries);
  py::array_t<Complex_matrix::StorageIndex> indices(entries), indptr(columns + 1);
  std::copy(matrix.valuePtr(), matrix.valuePtr() + entries, data.mutable_data());
  std::copy(matrix.innerIndexPtr(), matrix.innerIndexPtr() + entries, indices.mutable_data());
  std::copy(matrix.outerIndexPtr(), matrix.outerIndexPtr() + columns + 1, indptr.mutable_data());
  return py::make_tuple(data, indices, indptr, matrix.rows());
}

py::tuple result_state(const Result& r)
{
  return py::make_tuple(r.directions, r.magnitudes, r.coefficients, r.normals, r.tangent_frames, r.singular_faces,
                        r.loop_turns, r.eigenvalues, report_state(r.report));
}

Result result_from(const py::tuple& state)
{
  State_reader read(state);
  Result r;
  r.directions = read.next<py::array_t<double> >();
  r.magnitudes = read.next<py::array_t<double> >();
  r.coefficients = read.next<py::array_t<std::complex<double> > >();
  r.normals = read.next<py::array_t<double> >();
  r.tangent_frames = read.next<py::array_t<double> >();
  r.singular_faces = read.next<py::array_t<long long> >();
  r.loop_turns = read.next<py::array_t<long long> >();
  r.eigenvalues = read.next<std::vector<double> >();
  r.report = report_from(read.next<py::tuple>());
  check_state_degree(r.report.degree);
  const py::ssize_t nv = r.directions.ndim() > 0 ? r.directions.shape(0) : -1;
  check_state_shape(r.directions, {nv, 3}, "directions");
  check_state_shape(r.magnitudes, {nv}, "magnitudes");
  check_state_shape(r.coefficients, {nv}, "coefficients");
  check_state_shape(r.normals, {nv, 3}, "normals");
  check_state_shape(r.tangent_frames, {nv, 2, 3}, "tangent_frames");
  check_state_shape(r.singular_faces, {-1, 2}, "singular_faces");
  check_state_shape(r.loop_turns, {-1, 2}, "loop_turns");
  if(r.eigenvalues.size() != r.report.components.size())
    refuse("the pickled state's eigenvalues do not match its components");
  return with_read_only_arrays(std::move(r));
}

void bind_result(py::module_& m)
{
  py::class_<Result>(m, "Result", "One computed field: read-only numpy arrays and the solver's report.")
    .def_readonly("directions", &Result::directions, "unit tangent direction per vertex, shape (|V|, 3)")
    .def_readonly("magnitudes", &Result::magnitudes, "|u| per vertex before normalization, shape (|V|,)")
    .def_readonly("singular_faces", &Result::singular_faces,
                  "shape (k, 2): face, k for each singular face (index k / n)")
    .def_readonly("loop_turns", &Result::loop_turns,
                  "shape (m, 2): loop, turns for each loop along which the field turns other than the nearest "
                  "choice (give it back as prescribed_loop_turns with singular_faces as prescribed)")
    .def_readonly("eigenvalues", &Result::eigenvalues,
                  "the smallest eigenvalue per component (nan where not computed: see solves)")
    .def_property_readonly("solves", [](const Result& r) { return solve_names(r.report); },
                           "what gave each component its field: 'eigen-solve' (the smoothest field), 'linear solve' "
                           "(aligned or constrained: (A - lambda_t M) u = M q) or 'parallel section' (prescribed)")
    .def_property_readonly("degree", [](const Result& r) { return r.report.degree; },
                           "n: the number of directions at each vertex (1 vector, 2 line, 4 cross field)")
    .def_property_readonly("iterations", [](const Result& r) { return r.report.iterations; },
                           "the largest number of eigen-solve iterations over the components (0 without one)")
    .def_property_readonly("residual", [](const Result& r) { return r.report.residual; },
                           "the largest final residual over the components: |A u - lambda M u| / (s_A |M u|), "
                           "s_A = trace(A) / trace(M) of DirectionField.matrices(), so that it does not depend on "
                           "the mesh's scale (times s_A it is |A u - lambda M u| / |M u| as scipy gives it)")
    .def_property_readonly("converged", [](const Result& r) { return r.report.converged; },
                           "whether every component reached the tolerance (a linear solve always does)")
    .def_property_readonly("tangent_plane_vertices", [](const Result& r) { return r.report.tangent_plane_vertices; },
                           "vertices of folded triangles laid out in the fitted tangent plane (0 without folds)")
    .def_property_readonly("index_sum", [](const Result& r) { return r.report.index_sum; },
                           "sum of k over the singular faces (n times the Euler characteristic on closed meshes)")
    .def_property_readonly("component_index_sums", [](const Result& r) {
      std::vector<int> sums;
      for(const auto& c : r.report.components) sums.push_back(c.index_sum);
      return sums;
    })
    .def_property_readonly("component_euler_characteristics", [](const Result& r) {
      std::vector<int> chi;
      for(const auto& c : r.report.components) chi.push_back(c.euler_characteristic);
      return chi;
    })
    .def_property_readonly("timings", [](const Result& r) { return timings_of(r.report); }, "milliseconds")
    .def_readonly("coefficients", &Result::coefficients,
                  "(|V|,) complex128: per vertex u, |u| the magnitude, arg(u) n times the first direction's angle "
                  "from e1 with the vertex's angle sum scaled to 2 pi (the vectors DirectionField.matrices() acts on)")
    .def_readonly("normals", &Result::normals, "the unit normal per vertex about which the directions turn, (|V|, 3)")
    .def_readonly("tangent_frames", &Result::tangent_frames,
                  "(|V|, 2, 3): per vertex e1 along its reference edge (to its neighbour of smallest index; on the "
                  "boundary the boundary edge with the surface on its left) in the tangent plane, e2 = normal x e1")
    .def_property_readonly("all_directions", &all_directions,
                           "(|V|, n, 3): the n directions per vertex, the k-th the first turned by 2 pi k / n about "
                           "the normal (made when read: n |V| 3 numbers)")
    .def(py::pickle(&result_state, &result_from))
    .def("__repr__", [](const Result& r) {
      return "<Result degree=" + std::to_string(r.report.degree) + ", " + std::to_string(r.directions.shape(0)) +
             " vertices, " + std::to_string(r.singular_faces.shape(0)) + " singular faces, index_sum=" +
             std::to_string(r.report.index_sum) + (r.report.converged ? "" : ", not converged") + ">";
    });
}

const char* const compute_doc =
  "Computes the globally optimal n-direction field of the mesh.\n\n"
  "Keyword arguments (the named parameters of the C++ function):\n"
  "  degree=4            n: 1 vector, 2 line, 4 cross field ... (1 to 1000, as in C++ and the program)\n"
  "  s=0.0               the energy, in [-1, 1]: -1 anti-holomorphic, 0 Dirichlet, +1 holomorphic\n"
  "  align=None          'curvature' (= 'max-curvature'), 'min-curvature' or None (even n)\n"
  "  curvature_estimate  'quadric-fit' (default) or 'hopf'\n"
  "  guidance=None       (|V|, 3) vectors to follow (length = weight)\n"
  "  lambda_t / alignment_weight   how strongly an aligned field follows its guidance\n"
  "  eigenvalue_bound=False        also compute lambda_1 for aligned fields\n"
  "  constraints=None    (vertex ids, (k, 3) directions): hard constraints\n"
  "  boundary=None       'tangent' or 'normal': one direction along the boundary\n"
  "  feature_edges=None  (E, 2) vertex pairs, or feature_angle=DEG: sharp edges to follow (even n)\n"
  "  feature_cleanup=4   with feature_angle: cycles of at most 2N sharp edges lose their least sharp edge, then\n"
  "                      open chains of at most 2N and branches of at most N are dropped (0 keeps every one)\n"
  "  prescribed=None     (k, 2) face, k: place the singularities (index k / n)\n"
  "  prescribed_loop_turns=None   (m, 2) loop, turns: with prescribed, the field's turns along the mesh's loops\n"
  "                      (Result.loop_turns gives a field's own)\n"
  "  intrinsic_mollification=1e-6   relative margin of the fix for degenerate triangles (0: off)\n"
  "  normals=None        (|V|, 3): the normal of each vertex's tangent plane (C++ vertex_normal_map; default:\n"
  "                      the angle-weighted face normals)\n"
  "  max_iterations=1000, tolerance=1e-10, seed=0   the eigen-solve\n"
  "  progress=None       a callable(fraction) told the fraction done (0 to 1) at each step and solve;\n"
  "                      an exception it raises (or Ctrl-C) stops the computation and is raised\n"
  "Raises ValueError (InvalidInputError) for bad input, RuntimeError (SolverFailureError) if a solve fails.";

// A path as Python gives it (str or os.PathLike), refused if it holds a NUL.
std::string path_argument(const py::object& path)
{
  py::object text;
  try { text = py::module_::import("os").attr("fsdecode")(path); }
  catch(const py::error_already_set&) { throw py::type_error("path must be a str or an os.PathLike"); }
  const std::string p = py::cast<std::string>(text);
  if(p.find('\0') != std::string::npos) refuse("path contains a NUL character");
  return p;
}

// An index map as an int64 array (-1 where there is no index).
template <typename Index>
py::array_t<long long> index_array(const std::vector<Index>& map, Index none)
{
  py::array_t<long long> a(static_cast<py::ssize_t>(map.size()));
  auto r = a.mutable_unchecked<1>();
  for(py::ssize_t i = 0; i < r.shape(0); ++i)
  {
    const Index x = map[static_cast<std::size_t>(i)];
    r(i) = x == none ? -1 : static_cast<long long>(static_cast<std::size_t>(x));
  }
  return a;
}

py::dict file_maps(const Repaired_mesh<Mesh>& in)
{
  py::dict maps;
  maps["vertex_of_file_vertex"] = index_array(in.vertex_of_file_vertex, Mesh::null_vertex());
  maps["file_vertex_of_vertex"] = index_array(in.file_vertex_of_vertex, static_cast<std::size_t>(-1));
  maps["file_face_of_face"] = index_array(in.file_face_of_face, static_cast<std::size_t>(-1));
  return maps;
}

// A file that cannot be opened raises the OSError that open() raises
// (FileNotFoundError, PermissionError, IsADirectoryError), not a ValueError.
void check_readable(const std::string& path)
{
  const int fd = ::open(path.c_str(), O_RDONLY);
  struct stat status{};
  const bool directory = fd >= 0 && ::fstat(fd, &status) == 0 && S_ISDIR(status.st_mode);
  const int error = fd < 0 ? errno : EISDIR;
  if(fd >= 0) ::close(fd);
  if(fd >= 0 && !directory) return;
  errno = error;
  PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.c_str());
  throw py::error_already_set();
}

// (V, F, repairs[, maps]) of a repaired mesh, as read_mesh() and repair_mesh() return them.
py::tuple mesh_arrays(const Repaired_mesh<Mesh>& in, bool with_maps)
{
  py::array_t<double> V({static_cast<py::ssize_t>(in.mesh.number_of_vertices()), py::ssize_t(3)});
  py::array_t<long long> F({static_cast<py::ssize_t>(in.mesh.number_of_faces()), py::ssize_t(3)});
  auto v = V.mutable_unchecked<2>();
  auto f = F.mutable_unchecked<2>();
  for(Vertex_index x : in.mesh.vertices())
    for(int c = 0; c < 3; ++c) v(static_cast<py::ssize_t>(x), c) = in.mesh.point(x)[c];
  for(Face_index x : in.mesh.faces())
  {
    int c = 0;
    for(Vertex_index y : CGAL::vertices_around_face(in.mesh.halfedge(x), in.mesh))
      f(static_cast<py::ssize_t>(x), c++) = static_cast<long long>(y);
  }
  const Repair_report& r = in.report;
  py::dict repairs;
  repairs["merged_points"] = r.merged_points;
  repairs["degenerate_faces_removed"] = r.degenerate_polygons;
  repairs["polygons_triangulated"] = r.triangulated_polygons;
  repairs["repeated_faces_removed"] = r.repeated_triangles;
  repairs["faces_reoriented"] = r.reoriented_triangles;
  repairs["vertices_duplicated"] = r.duplicated_vertices;
  repairs["faces_skipped"] = r.skipped_triangles;
  repairs["unused_vertices_removed"] = r.unused_vertices;
  if(with_maps) return py::make_tuple(V, F, repairs, file_maps(in));
  return py::make_tuple(V, F, repairs);
}

py::tuple read_mesh(const py::object& path_object, bool with_maps)
{
  const std::string path = path_argument(path_object);
  check_readable(path);
  Repaired_mesh<Mesh> in;
  {
    py::gil_scoped_release release;
    try { in = read_and_repair_mesh<Mesh>(path); }
    catch(const Mesh_input_error& e) { throw py::value_error(e.what()); }
  }
  return mesh_arrays(in, with_maps);
}

// The polygons of F (an integer array of shape (m, k), k >= 3, or a sequence
// of index sequences of any lengths) into `soup`, each index checked.
void add_polygons(const py::object& F, Polygon_soup& soup)
{
  const bool rows = py::isinstance<py::array>(F);
  std::vector<Index_array> polygons;
  if(rows) polygons.push_back(integer_array(F, "F"));
  else
    for(const py::handle& polygon : py::iterable(F))
      polygons.push_back(integer_array(py::reinterpret_borrow<py::object>(polygon), "a polygon of F"));
  if(rows && (polygons[0].ndim() != 2 || polygons[0].shape(1) < 3))
    refuse("F must be an array of shape (number of faces, k) with k >= 3, or a list of polygons");
  const std::size_t count = rows ? static_cast<std::size_t>(polygons[0].shape(0)) : polygons.size();
  const std::size_t corners = rows ? static_cast<std::size_t>(polygons[0].shape(1)) : 0;
  for(std::size_t i = 0; i < count; ++i)
  {
    const Index_array& p = rows ? polygons[0] : polygons[i];
    const long long* first = p.data() + (rows ? i * corners : 0);
    const std::size_t size = rows ? corners : static_cast<std::size_t>(p.size());
    if(!rows && (p.ndim() != 1 || size < 3))
      refuse("F's polygon " + std::to_string(i) + " needs at least 3 vertex indices");
    for(std::size_t c = 0; c < size; ++c)
    {
      if(first[c] < 0 || static_cast<std::size_t>(first[c]) >= soup.points.size())
        refuse("F's polygon " + std::to_string(i) + " refers to vertex " + std::to_string(first[c]) + ", not in V");
      soup.corners.push_back(static_cast<std::size_t>(first[c]));
    }
    soup.end_polygon();
  }
}

// V and F repaired in memory, exactly as read_mesh() repairs a file's.
py::tuple repair_mesh(const py::object& V, const py::object& F, bool with_maps)
{
  const Float_array points = real_array(V, "V", "an array of numbers of shape (number of vertices, 3)");
  if(points.ndim() != 2 || points.shape(1) != 3) refuse("V must be an array of shape (number of vertices, 3)");
  Polygon_soup soup;
  const auto p = points.unchecked<2>();
  for(py::ssize_t i = 0; i < p.shape(0); ++i)
  {
    if(!(std::isfinite(p(i, 0)) && std::isfinite(p(i, 1)) && std::isfinite(p(i, 2))))
      refuse("V row " + std::to_string(i) + " has a non-finite coordinate");
    soup.points.push_back({p(i, 0), p(i, 1), p(i, 2)});
  }
  add_polygons(F, soup);
  if(soup.number_of_polygons() == 0) refuse("F holds no face");
  Repaired_mesh<Mesh> in;
  {
    py::gil_scoped_release release;
    try { in = repair_into_mesh<Mesh>(soup, "F"); }
    catch(const Mesh_input_error& e) { throw py::value_error(e.what()); }
  }
  return mesh_arrays(in, with_maps);
}

// The object behind `self`; an instance made by __new__ alone has none.
Direction_field_object& initialized(Direction_field_object* f)
{
  if(f == nullptr || !f->constructed())
    throw py::type_error("DirectionField.__init__(V, F) was not called on this object");
  return *f;
}

void bind_field(py::module_& m)
{
  py::class_<Direction_field_object>(m, "DirectionField",
                                     "A mesh prepared once (indexing, geometry, components); compute() then reuses "
                                     "the connection, matrices and factorizations of earlier calls, as the C++ class "
                                     "Globally_optimal_direction_field does.")
    .def(py::init<const py::object&, const py::object&>(), py::arg("V"), py::arg("F"),
         "V: (|V|, 3) float64 vertex positions; F: (|F|, 3) integer triangles (an oriented manifold mesh)")
    .def("compute", [](Direction_field_object* f, const py::kwargs& kw) { return initialized(f).compute(kw); },
         compute_doc)
    .def("_matrices",
         [](Direction_field_object* f, const py::object& degree, double s, double mollification) {
           std::pair<Complex_matrix, Complex_matrix> am =
             initialized(f).matrices(degree_option(degree), s, mollification);
           return py::make_tuple(compressed_columns(std::move(am.first)), compressed_columns(std::move(am.second)));
         },
         py::kw_only(), py::arg("degree"), py::arg("s"), py::arg("intrinsic_mollification"),
         "the arrays of A and M (DirectionField.matrices() makes them scipy.sparse matrices)")
    .def_property_readonly("construction_ms", [](Direction_field_object* f) { return initialized(f).construction_ms(); },
                           "milliseconds of the C++ class's mesh work (indexing, geometry, components; 0 before the first compute())")
    .def("__repr__", [](Direction_field_object* f) {
      return f != nullptr && f->constructed() ? "<DirectionField " + std::to_string(f->vertices()) + " vertices, " +
                                                  std::to_string(f->faces()) + " faces>"
                                              : std::string("<DirectionField, __init__ not called>");
    });
  m.attr("_compute_doc") = compute_doc;  // the package's wrappers (__init__.py) show it with their signature
  m.def("compute_globally_optimal_directions",
        [](const py::object& V, const py::object& F, const py::kwargs& kwargs) {
          Direction_field_object field(V, F);
          return field.compute(kwargs, true);
        },
        py::arg("V"), py::arg("F"), compute_doc);
  m.def("_read_mesh", &read_mesh, py::arg("path"), py::kw_only(), py::arg("with_maps") = false,
        "(V, F, repairs[, maps]) of a file (the package's read_mesh() makes them a MeshArrays)");
  m.def("_repair_mesh", &repair_mesh, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("with_maps") = false,
        "(V, F, repairs[, maps]) of arrays (the package's repair_mesh() makes them a MeshArrays)");
}

}  // namespace

#endif
