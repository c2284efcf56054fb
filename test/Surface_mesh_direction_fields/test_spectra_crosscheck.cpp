// The smallest eigenvalue found by the package (inverse iteration on its own
// assembly) against an independent solve by Spectra: shift-invert Lanczos on
// the real 2N x 2N embedding of the Hermitian pencil,
//     [Re A  -Im A]        [Re M  -Im M]
//     [Im A   Re A]  x = l [Im M   Re M] x,
// where every eigenvalue of A u = l M u appears twice. Meshes up to ~11k
// vertices; relative agreement 1e-8.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
// the package's own assembly, compared (the field comes from the compiled engine)
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include "test_types.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace SI = CGAL::Surface_mesh_direction_fields::internal;
typedef Eigen::SparseMatrix<double> Real_sparse;

static Real_sparse real_embedding(const SI::Complex_sparse_matrix& H)
{
  const Eigen::Index n = H.rows();
  std::vector<Eigen::Triplet<double> > t;
  for(Eigen::Index c = 0; c < H.outerSize(); ++c)
    for(SI::Complex_sparse_matrix::InnerIterator it(H, c); it; ++it)
    {
      const Eigen::Index i = it.row(), j = it.col();
      const double re = it.value().real(), im = it.value().imag();
      t.emplace_back(i, j, re);
      t.emplace_back(i + n, j + n, re);
      t.emplace_back(i + n, j, im);
      t.emplace_back(i, j + n, -im);
    }
  Real_sparse R(2 * n, 2 * n);
  R.setFromTriplets(t.begin(), t.end());
  return R;
}

// Smallest eigenvalue of the pencil by Spectra, or NaN on failure.
static double spectra_smallest_eigenvalue(const SI::Energy_and_mass& em)
{
  const Real_sparse A = real_embedding(em.energy), M = real_embedding(em.mass);
  const double sigma = -1e-6 * A.diagonal().sum() / M.diagonal().sum();  // just below 0: A is only PSD
  typedef Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse> Op;
  typedef Spectra::SparseSymMatProd<double> BOp;
  Op op(A, M);
  BOp bop(M);
  Spectra::SymGEigsShiftSolver<Op, BOp, Spectra::GEigsMode::ShiftInvert> solver(op, bop, 4, 30, sigma);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-13);
  if(solver.info() != Spectra::CompInfo::Successful) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::VectorXd values = solver.eigenvalues();
  return values.minCoeff();
}

static void compare(Test_report& report, const std::string& name, Mesh& mesh, int n, double s)
{
  auto dir = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:direction").first;
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
    mesh, dir, CGAL::parameters::degree(n).smoothness_parameter(s).residual_tolerance(1e-12).number_of_iterations(20000));

  const SI::Indexed_mesh m = SI::make_indexed_mesh(
    mesh, [&](Mesh::Vertex_index v) { const auto& p = mesh.point(v); return SI::Vec3{p.x(), p.y(), p.z()}; },
    get(CGAL::vertex_index, mesh), get(CGAL::face_index, mesh));
  const SI::Tangent_spaces ts = SI::compute_tangent_spaces(m);
  const SI::Connection con = SI::compute_connection(m, ts, n);
  const SI::Components comps = SI::split_into_components(m);
  const SI::Energy_and_mass em = SI::assemble_energy_and_mass(m, ts, con, comps.list[0], comps.local_index, s);
  const double reference = spectra_smallest_eigenvalue(em);
  const double ours = r.components[0].eigenvalue.value();
  const double scale = em.energy.diagonal().real().sum() / em.mass.diagonal().real().sum();
  // relative to the eigenvalue, or to the spectrum's scale when it is ~0 (flat cases)
  const double err = std::abs(ours - reference) / (std::max)(std::abs(reference), 1e-6 * scale);
  std::cout << name << " n = " << n << " s = " << s << ": ours " << ours << " (" << r.iterations
            << " iterations), Spectra " << reference << ", relative difference " << err << "\n";
  report.check(err <= 1e-8, name + ": eigenvalue agrees with Spectra, n = " + std::to_string(n) +
                            ", s = " + std::to_string(s));
}

int main()
{
  Test_report report("Spectra cross-check");
  Mesh lumpy;
  make_icosphere(lumpy, 4);
  for(auto v : lumpy.vertices())
  {
    const Kernel::Vector_3 p = lumpy.point(v) - CGAL::ORIGIN;
    lumpy.point(v) = CGAL::ORIGIN + (1. + 0.15 * std::sin(4. * p.x()) * std::cos(3. * p.y() + 0.5 * p.z())) * p;
  }
  for(int n : {1, 2, 4})
    for(double s : {-1., 0., 1.})
      compare(report, "lumpy sphere", lumpy, n, s);

  for(const char* name : {"torus_oded.off", "spot.off", "cow.off", "eight.off", "fertility.off", "fandisk.off",
                          "camelhead.off", "blade.off", "plane_holes.off", "sphere_oded.off"})
  {
    const std::string path = shared_mesh_path(name);
    if(path.empty()) continue;
    Mesh mesh;
    if(!report.check(CGAL::IO::read_polygon_mesh(path, mesh), std::string("read ") + name)) continue;
    compare(report, name, mesh, 4, 0.);
    compare(report, name, mesh, 1, 1.);
  }
  return report.finish();
}
