// compute_face_directions(): the field on faces (C++
// compute_globally_optimal_face_directions()) as numpy arrays: a direction
// per face and its rotation by 2 pi / n (libigl's PD1 and PD2 for n = 4), the
// singular vertices, the period jump and the mismatch per face edge.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PYTHON_FACE_FIELD_H
#define SURFACE_MESH_DIRECTION_FIELDS_PYTHON_FACE_FIELD_H

#include "python_results.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh_direction_fields/feature_edges.h>
#include <CGAL/Surface_mesh_direction_fields/globally_optimal_face_directions.h>

namespace {

struct Face_field_result
{
  py::array_t<double> face_directions, pd2;
  py::array_t<long long> singular_vertices, matching, mismatch;
  SMDF::Face_direction_field_result report;
};

const char* const face_option_names[] = {"degree", "align", "boundary", "guidance", "alignment_weight", "lambda_t",
                                         "constraints", "feature_edges", "feature_angle", "feature_cleanup", "prescribed",
                                         "singularity_cancellation_radius", "intrinsic_mollification",
                                         "max_iterations", "tolerance", "seed", "vertex_point_index"};

struct Face_options
{
  Options common;                                                   // degree, align, boundary, features, ...
  std::vector<Kernel::Vector_3> guidance;                           // per face; empty: none
  std::vector<std::pair<Face_index, Kernel::Vector_3> > constraints;  // (face, direction)
  std::optional<std::vector<std::pair<Vertex_index, int> > > prescribed;  // (vertex, k)
  double cancellation_radius = 0.;  // singularity_cancellation_radius
  std::vector<std::size_t> point_of_vertex;  // vertex_point_index; else each vertex its own point
};

// vertex_point_index (|V|,): the point each vertex copies (repair_mesh's
// 'file_vertex_of_vertex'): faces around a non-manifold edge are glued there.
void read_vertex_points(const py::object& value, const Mesh& mesh, Face_options& o)
{
  const Index_array a = integer_array(value, "vertex_point_index");
  if(a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != mesh.number_of_vertices())
    refuse("vertex_point_index must have one entry per vertex (" + std::to_string(mesh.number_of_vertices()) + ")");
  const auto r = a.unchecked<1>();
  for(py::ssize_t v = 0; v < a.shape(0); ++v)
  {
    if(r(v) < 0) refuse("vertex_point_index: vertex " + std::to_string(v) + " has a negative point");
    o.point_of_vertex[static_cast<std::size_t>(v)] = static_cast<std::size_t>(r(v));
  }
}

// prescribed = k x 2 (vertex, k): index k / n at interior vertices
void read_prescribed_vertices(const py::object& value, const Mesh& mesh, Face_options& o)
{
  const Index_array p = index_rows(value, 2, "prescribed");
  const auto r = p.unchecked<2>();
  std::vector<std::pair<Vertex_index, int> > vertices;
  for(py::ssize_t i = 0; i < p.shape(0); ++i)
  {
    if(r(i, 0) < 0 || static_cast<std::size_t>(r(i, 0)) >= mesh.number_of_vertices())
      refuse("prescribed row " + std::to_string(i) + ": vertex " + std::to_string(r(i, 0)) +
             " is not a vertex of the mesh");
    if(std::abs(r(i, 1)) > 1000000) refuse("prescribed row " + std::to_string(i) + ": k out of range");
    vertices.emplace_back(Vertex_index(static_cast<Mesh::size_type>(r(i, 0))), static_cast<int>(r(i, 1)));
  }
  o.prescribed = std::move(vertices);
}

// constraints = (face ids, directions k x 3)
void read_face_constraints(const py::object& value, const Mesh& mesh, Face_options& o)
{
  const Constraint_arrays c = constraint_arrays(value, "face");
  const Index_array& ids = c.ids;
  const auto id = ids.unchecked<1>();
  const auto dir = c.directions.unchecked<2>();
  for(py::ssize_t i = 0; i < ids.shape(0); ++i)
  {
    if(id(i) < 0 || static_cast<std::size_t>(id(i)) >= mesh.number_of_faces())
      refuse("constraints: face " + std::to_string(id(i)) + " is not a face of the mesh");
    o.constraints.emplace_back(Face_index(static_cast<Mesh::size_type>(id(i))),
                               Kernel::Vector_3(dir(i, 0), dir(i, 1), dir(i, 2)));
  }
}

Face_options read_face_options(const py::dict& kw, Mesh& mesh)
{
  py::dict common;
  for(const auto& item : kw)
  {
    const std::string key = py::cast<std::string>(item.first);
    if(std::find(std::begin(face_option_names), std::end(face_option_names), key) == std::end(face_option_names))
      throw py::type_error("unexpected keyword argument '" + key + "'");
    if(key != "guidance" && key != "constraints" && key != "prescribed" && key != "singularity_cancellation_radius" &&
       key != "vertex_point_index")
      common[item.first] = item.second;
  }
  Face_options o;
  const bool guided = kw.contains("guidance") && !kw["guidance"].is_none();
  if(guided)  // a zero placeholder (no preference anywhere), so that the shared checks know a guidance is given
  {
    py::array_t<double> placeholder({py::ssize_t(mesh.number_of_vertices()), py::ssize_t(3)});
    std::fill(placeholder.mutable_data(), placeholder.mutable_data() + placeholder.size(), 0.);
    common["guidance"] = placeholder;
  }
  o.common = read_options(common, mesh);  // the shared keywords, checked as for vertex fields
  o.common.guidance.clear();
  if(guided)
  {
    const Float_array g = rows_of_three(kw["guidance"], mesh.number_of_faces(), "guidance");
    const auto r = g.unchecked<2>();
    for(py::ssize_t i = 0; i < g.shape(0); ++i) o.guidance.emplace_back(r(i, 0), r(i, 1), r(i, 2));
  }
  if(kw.contains("constraints") && !kw["constraints"].is_none()) read_face_constraints(kw["constraints"], mesh, o);
  if(kw.contains("prescribed") && !kw["prescribed"].is_none())
  {
    if(o.common.alignment_weight || o.common.lambda_t)
      refuse("prescribed singularities take no lambda_t or alignment_weight");
    read_prescribed_vertices(kw["prescribed"], mesh, o);
  }
  o.point_of_vertex.resize(mesh.number_of_vertices());
  for(std::size_t v = 0; v < o.point_of_vertex.size(); ++v) o.point_of_vertex[v] = v;
  if(kw.contains("vertex_point_index") && !kw["vertex_point_index"].is_none())
    read_vertex_points(kw["vertex_point_index"], mesh, o);
  if(kw.contains("singularity_cancellation_radius") && !kw["singularity_cancellation_radius"].is_none())
    o.cancellation_radius = option_as<double>(kw["singularity_cancellation_radius"],
                                              "singularity_cancellation_radius", "a number");
  return o;
}

// The library call (without the GIL) with the options' named parameters.
SMDF::Face_direction_field_result compute_on_faces(Mesh& mesh, const Face_options& o,
                                                   std::vector<Kernel::Vector_3>& directions,
                                                   std::vector<std::pair<Vertex_index, int> >& singular,
                                                   std::vector<int>& matching)
{
  std::vector<unsigned char> is_feature(mesh.number_of_edges(), 0);
  for(Edge_index e : o.common.features) is_feature[e] = 1;
  if(o.common.feature_angle)
    SMDF::detect_feature_edges(mesh, *o.common.feature_angle, CGAL::make_property_map(is_feature),
                               CGAL::parameters::feature_cleanup_steps(o.common.feature_cleanup));
  std::vector<Kernel::Vector_3> guidance = o.guidance;
  std::vector<unsigned char> constrained(mesh.number_of_faces(), 0);
  std::vector<Kernel::Vector_3> wanted(mesh.number_of_faces(), CGAL::NULL_VECTOR);
  for(const auto& c : o.constraints) { constrained[c.first] = 1; wanted[c.first] = c.second; }
  const auto np = CGAL::parameters::degree(o.common.degree)
                    .principal_curvature_alignment(o.common.align)
                    .boundary_alignment(o.common.boundary)
                    .number_of_iterations(o.common.max_iterations)
                    .residual_tolerance(o.common.tolerance)
                    .random_seed(o.common.seed)
                    .intrinsic_mollification(o.common.intrinsic_mollification)
                    .edge_is_feature_map(CGAL::make_property_map(is_feature))
                    .face_is_constrained_map(CGAL::make_property_map(constrained))
                    .face_constrained_direction_map(CGAL::make_property_map(wanted))
                    .singularities_output_iterator(std::back_inserter(singular))
                    .edge_matching_map(CGAL::make_property_map(matching))
                    .singularity_cancellation_radius(o.cancellation_radius)
                    .vertex_point_index_map(CGAL::make_property_map(o.point_of_vertex));
  auto out = CGAL::make_property_map(directions);
  auto with_guidance = [&](auto np_) {
    if(guidance.empty()) return SMDF::compute_globally_optimal_face_directions(mesh, out, np_);
    return SMDF::compute_globally_optimal_face_directions(mesh, out, np_.face_guidance_map(CGAL::make_property_map(guidance)));
  };
  if(o.prescribed) return with_guidance(np.prescribed_singularities(*o.prescribed));
  if(o.common.alignment_weight) return with_guidance(np.alignment_weight(*o.common.alignment_weight));
  if(o.common.lambda_t) return with_guidance(np.alignment_lambda(*o.common.lambda_t));
  return with_guidance(np);
}

// The jump across each side of each face: F[f, c] -> F[f, (c+1) % 3], from f to the face across.
py::array_t<long long> face_side_jumps(const Mesh& mesh, const Index_array& F, const std::vector<int>& matching)
{
  py::array_t<long long> jumps({static_cast<py::ssize_t>(mesh.number_of_faces()), py::ssize_t(3)});
  auto j = jumps.mutable_unchecked<2>();
  const auto rows = F.unchecked<2>();
  for(py::ssize_t f = 0; f < rows.shape(0); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const Vertex_index a(static_cast<Mesh::size_type>(rows(f, c))), b(static_cast<Mesh::size_type>(rows(f, (c + 1) % 3)));
      const auto h = CGAL::halfedge(a, b, mesh).first;  // in face f: make_mesh() keeps the rows' orientation
      // the edge as edges() lists it (Surface_mesh's edge(h) remembers h as its halfedge)
      const Edge_index listed(static_cast<Mesh::size_type>(std::size_t(mesh.edge(h))));
      const bool border = mesh.is_border(mesh.opposite(h));
      j(f, c) = border ? 0 : mesh.halfedge(listed) == h ? matching[listed] : -matching[listed];
    }
  return jumps;
}

Face_field_result with_read_only_arrays(Face_field_result r)
{
  make_read_only(r.face_directions, r.pd2, r.singular_vertices, r.matching, r.mismatch);
  return r;
}

// The unit normal of face f at any scale of the coordinates (PMP's
// compute_face_normal() squares a raw cross product, which overflows from
// coordinates near 1e77).
inline Kernel::Vector_3 unit_face_normal(const Mesh& mesh, Face_index f)
{
  const SMDF::internal::Vec3 n = SMDF::internal::unit_face_normal(f, mesh, mesh.points());
  return Kernel::Vector_3(n[0], n[1], n[2]);
}

Face_field_result compute_face_directions(const py::object& V, const py::object& F, const py::kwargs& kw)
{
  const Index_array rows = integer_array(F, "F");
  Mesh mesh = make_mesh(real_array(V, "V", "an array of numbers of shape (number of vertices, 3)"), rows);
  const Face_options o = read_face_options(kw, mesh);
  std::vector<Kernel::Vector_3> directions(mesh.number_of_faces(), CGAL::NULL_VECTOR);
  std::vector<std::pair<Vertex_index, int> > singular;
  std::vector<int> matching(mesh.number_of_edges(), 0);
  Face_field_result r;
  {
    py::gil_scoped_release release;
    r.report = compute_on_faces(mesh, o, directions, singular, matching);
  }
  const py::ssize_t nf = static_cast<py::ssize_t>(mesh.number_of_faces());
  r.face_directions = py::array_t<double>({nf, py::ssize_t(3)});
  r.pd2 = py::array_t<double>({nf, py::ssize_t(3)});
  auto d = r.face_directions.mutable_unchecked<2>();
  auto d2 = r.pd2.mutable_unchecked<2>();
  const double turn = 2. * CGAL_PI / o.common.degree;
  for(Face_index f : mesh.faces())
  {
    const Kernel::Vector_3 normal = unit_face_normal(mesh, f);
    const Kernel::Vector_3& x = directions[f];
    const Kernel::Vector_3 y = std::cos(turn) * x + std::sin(turn) * CGAL::cross_product(normal, x);
    for(int c = 0; c < 3; ++c) { d(py::ssize_t(f), c) = x[c]; d2(py::ssize_t(f), c) = y[c]; }
  }
  r.singular_vertices = py::array_t<long long>({static_cast<py::ssize_t>(singular.size()), py::ssize_t(2)});
  auto s = r.singular_vertices.mutable_unchecked<2>();
  for(std::size_t i = 0; i < singular.size(); ++i)
  {
    s(py::ssize_t(i), 0) = static_cast<long long>(singular[i].first);
    s(py::ssize_t(i), 1) = singular[i].second;
  }
  r.matching = face_side_jumps(mesh, rows, matching);
  r.mismatch = py::array_t<long long>({nf, py::ssize_t(3)});
  auto jm = r.matching.unchecked<2>();
  auto mm = r.mismatch.mutable_unchecked<2>();
  const long long n = o.common.degree;
  for(py::ssize_t f = 0; f < nf; ++f)
    for(int c = 0; c < 3; ++c) mm(f, c) = ((jm(f, c) % n) + n) % n;
  return with_read_only_arrays(std::move(r));
}

const char* const face_doc =
  "compute_face_directions(V, F, /, *, degree=4, align=None, guidance=None, lambda_t=None, alignment_weight=None,\n"
  "                        constraints=None, boundary=None, feature_edges=None, feature_angle=None, feature_cleanup=4,\n"
  "                        prescribed=None, singularity_cancellation_radius=0.0, intrinsic_mollification=1e-6,\n"
  "                        max_iterations=1000, tolerance=1e-10,\n"
  "                        seed=0, vertex_point_index=None)\n\n"
  "The smoothest (or aligned) n-direction field on the faces of the mesh (V, F): one direction per face,\n"
  "singularities at vertices, the principal matching per edge (user manual, 'Fields on Faces'). guidance is\n"
  "(|F|, 3), constraints a pair (face ids, directions). Returns a FaceField: face_directions and pd2 (|F|, 3;\n"
  "pd2 is the first direction turned by 2 pi / n: libigl's PD1 and PD2 for n = 4), singular_vertices (k, 2:\n"
  "vertex, k; the index is k / n), matching (|F|, 3: the period jump across edge F[f, c] -> F[f, (c+1) % 3],\n"
  "from f to the face across), mismatch (the same modulo n, as MIQ takes it), and the report.\n"
  "prescribed (k, 2: vertex, k) places the singularities at interior vertices instead: any indices that add up\n"
  "to n chi on each closed component are shown exactly, the matching included (non_principal_jumps counts the\n"
  "edges where it is not the principal one, which readers that recompute it would read differently).\n"
  "singularity_cancellation_radius > 0 removes the pairs of singular vertices of opposite index at most that far\n"
  "apart along the edges (a fraction of the bounding box's diagonal, e.g. 0.1) and returns the parallel field\n"
  "with the others or, with features, constraints, boundary, lambda_t or alignment_weight, the same field turned\n"
  "off the constrained faces: fewer irregular vertices in quad meshes (cancelled_pairs counts them).\n"
  "vertex_point_index (|V|,) keeps a non-manifold surface whole: vertices with the same value are copies of one\n"
  "point (repair_mesh(V, F, with_maps=True).maps['file_vertex_of_vertex']), and the faces around an edge of\n"
  "three faces or more are glued there (not with prescribed or singularity_cancellation_radius).";

void bind_face_field(py::module_& m)
{
  py::class_<Face_field_result>(m, "FaceField", "A field on faces: read-only arrays and the report of one computation.")
    .def_readonly("face_directions", &Face_field_result::face_directions, "(|F|, 3) unit direction per face")
    .def_readonly("pd2", &Face_field_result::pd2, "(|F|, 3) the direction turned by 2 pi / n about the face normal")
    .def_readonly("singular_vertices", &Face_field_result::singular_vertices, "(k, 2) int64: vertex, k")
    .def_readonly("matching", &Face_field_result::matching, "(|F|, 3) int64 period jump per face edge")
    .def_readonly("mismatch", &Face_field_result::mismatch, "(|F|, 3) int64 matching modulo n")
    .def_property_readonly("degree", [](const Face_field_result& r) { return r.report.degree; })
    .def_property_readonly("index_sum", [](const Face_field_result& r) { return r.report.index_sum; })
    .def_property_readonly("converged", [](const Face_field_result& r) { return r.report.converged; })
    .def_property_readonly("eigenvalues", [](const Face_field_result& r) {
      std::vector<double> values;
      for(const auto& c : r.report.components) values.push_back(nan_if_absent(c.eigenvalue));
      return values;
    })
    .def_property_readonly("solves", [](const Face_field_result& r) { return solve_names(r.report); },
                           "per component: 'eigen-solve', 'linear solve' or 'parallel section'")
    .def_property_readonly("boundary_indices", [](const Face_field_result& r) {
      std::vector<long long> values;
      for(const auto& c : r.report.components) values.push_back(c.boundary_index);
      return values;
    })
    .def_property_readonly("euler_characteristics", [](const Face_field_result& r) {
      std::vector<int> values;
      for(const auto& c : r.report.components) values.push_back(c.euler_characteristic);
      return values;
    })
    .def_property_readonly("prescribed", [](const Face_field_result& r) { return r.report.prescribed; })
    .def_property_readonly("non_principal_jumps",
                           [](const Face_field_result& r) { return r.report.number_of_non_principal_jumps; })
    .def_property_readonly("cancelled_pairs",
                           [](const Face_field_result& r) { return r.report.number_of_cancelled_pairs; },
                           "pairs of opposite singular vertices removed by singularity_cancellation_radius")
    .def_property_readonly("glued_edges", [](const Face_field_result& r) { return r.report.number_of_glued_edges; },
                           "non-manifold edges across which the faces share the field (vertex_point_index)")
    .def(py::pickle(
      [](const Face_field_result& r) {
        return py::make_tuple(r.face_directions, r.pd2, r.singular_vertices, r.matching, r.mismatch,
                              face_report_state(r.report));
      },
      [](const py::tuple& state) {
        State_reader read(state);
        Face_field_result r;
        r.face_directions = read.next<py::array_t<double> >();
        r.pd2 = read.next<py::array_t<double> >();
        r.singular_vertices = read.next<py::array_t<long long> >();
        r.matching = read.next<py::array_t<long long> >();
        r.mismatch = read.next<py::array_t<long long> >();
        r.report = face_report_from(read.next<py::tuple>());
        check_state_degree(r.report.degree);
        const py::ssize_t nf = r.face_directions.ndim() > 0 ? r.face_directions.shape(0) : -1;
        check_state_shape(r.face_directions, {nf, 3}, "face_directions");
        check_state_shape(r.pd2, {nf, 3}, "pd2");
        check_state_shape(r.singular_vertices, {-1, 2}, "singular_vertices");
        check_state_shape(r.matching, {nf, 3}, "matching");
        check_state_shape(r.mismatch, {nf, 3}, "mismatch");
        return with_read_only_arrays(std::move(r));
      }))
    .def("__repr__", [](const Face_field_result& r) {
      return "<FaceField n=" + std::to_string(r.report.degree) + ", " + std::to_string(r.face_directions.shape(0)) +
             " faces, " + std::to_string(r.singular_vertices.shape(0)) + " singular vertices>";
    });
  m.def("compute_face_directions",
        [](const py::object& V, const py::object& F, const py::kwargs& kw) { return compute_face_directions(V, F, kw); },
        py::arg("V"), py::arg("F"), face_doc);
}

}  // namespace

#endif
