// The building blocks, checked against exact expectations:
//  * tangent spaces and connection: r_ji = conj(r_ij) across every interior
//    edge, exp(i Omega_t) = r_ij r_jk r_ki, and Gauss-Bonnet sum Omega = 2 pi n chi;
//  * on a planar mesh, the energy matrix is the cotan Laplacian, conjugated by
//    the phases of the vertex bases (A = P^* L P), and M is scale-covariant;
//  * A and M are Hermitian, A is positive semi-definite for s = -1, 0, 1;
//  * on a round sphere of radius R, lambda_1 = n (1 - s) / R^2 (pins every sign
//    and conjugation of the user manual, section "Local Matrices");
//  * the coarse estimate of the eigen-solve: the coarse matrices are P^* A P
//    and P^* M P, the bound is >= lambda_1, and the shifted factorization (or
//    its fallback, when the shift is too large) gives the eigenpair of the
//    unshifted solve, and a rejected trial shift prints nothing;
//  * the matrices handed to the solver: A + shift M, or its lower triangle for
//    the Cholesky solvers, equal to Eigen's sum bit for bit; the parallel
//    basis products of the eigen-solve equal Eigen's;
//  * the components: each vertex and face in exactly one, in a fixed order;
//  * the parallel solve with CHOLMOD's supernodal factor: CHOLMOD's solution,
//    the same bits on any number of threads, a plan of whole subtrees.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/subnormals.h>

#include "test_types.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <atomic>
#include <cmath>
#include <sstream>
#include <memory>
#include <fstream>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <complex>
#include <iostream>
#include <limits>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace SI = CGAL::Surface_mesh_direction_fields::internal;
typedef std::complex<double> Complex;

#include "test_matrices_method.h"
#include "test_matrices_eigen_solve.h"
#include "test_matrices_factorization.h"

int main()
{
  Test_report report("matrices");
  check_huge_page_advice(report);
  check_subnormals_flushed(report);
  check_components(report);

  {
    Mesh lumpy;
    make_lumpy_sphere(lumpy, 5);
    typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<SI::Complex_sparse_matrix> > Ldlt;
    report.check(SI::Factored_matrix<Ldlt>::detects_indefinite, "Eigen's LDLT detects indefinite matrices");
    report.check(SI::Reads_lower_triangle<Eigen::SimplicialLDLT<SI::Complex_sparse_matrix> >::value &&
                   !SI::Reads_lower_triangle<Eigen::SimplicialLDLT<SI::Complex_sparse_matrix, Eigen::Upper> >::value &&
                   !SI::Reads_lower_triangle<Eigen::SparseLU<SI::Complex_sparse_matrix> >::value,
                 "only the solvers reading the lower triangle are given the lower triangle");
    check_shifted_eigen_solve<Ldlt>(report, "lumpy sphere, LDLT", lumpy, 4, 0.);
    check_shifted_eigen_solve<Ldlt>(report, "lumpy sphere, LDLT", lumpy, 1, 0.5);
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
    typedef CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<SI::Complex_sparse_matrix> > Eigen_cholmod;
    report.check(SI::Factored_matrix<Eigen_cholmod>::detects_indefinite &&
                   SI::Factored_matrix<Eigen_cholmod>::factors_lower_triangle,
                 "Eigen's CHOLMOD LLT detects indefinite matrices and reads the lower triangle");
    check_shifted_eigen_solve<Eigen_cholmod>(report, "lumpy sphere, Eigen's CHOLMOD", lumpy, 4, 0.);
    typedef SMDF::Cholmod_supernodal_solver Cholmod;
    check_shifted_eigen_solve<Cholmod>(report, "lumpy sphere, CHOLMOD", lumpy, 4, 0.);
    check_shifted_eigen_solve<Cholmod>(report, "lumpy sphere, CHOLMOD", lumpy, 2, -0.5);
    check_parallel_supernodal_solve(report, 3);
    {
      // two one-column supernodes, the second with a row in the first: not a
      // postordered elimination tree, so no plan (CHOLMOD's solve is used)
      const int super[] = {0, 1, 2}, row_start[] = {0, 1, 3}, rows[] = {0, 1, 0}, value_start[] = {0, 1, 3};
      const Complex values[] = {1., 1., 0.5};
      SI::Supernodal_factor_view<int> view;
      view.n = 2;
      view.supernodes = 2;
      view.super = super;
      view.row_start = row_start;
      view.rows = rows;
      view.value_start = value_start;
      view.values = values;
      report.check(!SI::Supernodal_solve_plan(view).valid(), "parallel supernodal solve: a tree not in postorder is refused");
    }
    check_parallel_supernodal_solve(report, 200);
    check_cholmod_solver_concept(report);
    check_nested_dissection_orderings(report);
    check_blas_threads_restored(report);
    // the subtrees with Eigen's kernels (the default), then with OpenBLAS on one thread
    for(bool thread_control : {false, true})
    {
      SMDF::set_openblas_thread_control(thread_control);
      check_parallel_factorization(report, 3);
      check_parallel_factorization(report, 40);
      check_parallel_factorization(report, 200);
    }
    SMDF::set_openblas_thread_control(false);
    check_single_precision_factorization(report, 200);
#endif
  }

  {
    // the 32-bit indices of the indexed mesh read back as std::size_t, the sentinel included
    auto round_trip = [](std::size_t i) { return static_cast<std::size_t>(SI::Compact_index(i)) == i; };
    report.check(sizeof(SI::Compact_index) == 4 && round_trip(0) && round_trip(123456789) &&
                   round_trip(SI::Compact_index::largest) && round_trip(SI::no_index),
                 "compact indices: 4 bytes, 0, 123456789, the largest index and no_index read back unchanged");
  }

  {
    // the parallel basis products of the eigen-solve against Eigen's own, on
    // a row count that is not a multiple of the chunk size
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(SI::parallel_grain_size) + 17;
    const SI::Complex_dense_matrix V = SI::Complex_dense_matrix::Random(rows, 7),
                                   X = SI::Complex_dense_matrix::Random(rows, 2),
                                   Y = SI::Complex_dense_matrix::Random(rows, 1),
                                   C = SI::Complex_dense_matrix::Random(7, 3);
    SI::Complex_dense_matrix VX, VY, VC, W = X.leftCols(1);
    SI::adjoint_products(V, X, Y, VX, VY);
    SI::combine_columns(V, C, VC);
    SI::combine_columns(V.leftCols(2), C.topLeftCorner(2, 1), W, true);
    const SI::Complex_dense_matrix VX_ref = V.adjoint() * X, VY_ref = V.adjoint() * Y, VC_ref = V * C;
    const SI::Complex_dense_matrix W_ref = X.leftCols(1) - V.leftCols(2) * C.topLeftCorner(2, 1);
    report.check((VX - VX_ref).norm() <= 1e-13 * VX_ref.norm() && (VY - VY_ref).norm() <= 1e-13 * VY_ref.norm() &&
                   (VC - VC_ref).norm() <= 1e-14 * VC_ref.norm() && (W - W_ref).norm() <= 1e-14 * W_ref.norm() &&
                   SI::adjoint_product(V, X) == VX,
                 "basis products V^* X, V^* Y, V C and W - V C equal Eigen's");

    // the weighted products of the orthonormalization, and the orthonormalization
    // itself for one column (in place, in parallel) and for two (column by column)
    const Eigen::VectorXd d = Eigen::VectorXd::Random(rows).cwiseAbs() + Eigen::VectorXd::Constant(rows, 0.1);
    const SI::Complex_dense_matrix VDX_ref = V.adjoint() * d.asDiagonal() * X;
    Eigen::VectorXd norms_ref(2);
    for(Eigen::Index j = 0; j < 2; ++j) norms_ref[j] = std::sqrt(X.col(j).cwiseAbs2().dot(d));
    report.check((SI::weighted_adjoint_product(V, d, X) - VDX_ref).norm() <= 1e-13 * VDX_ref.norm() &&
                   (SI::weighted_column_norms(d, X) - norms_ref).norm() <= 1e-14 * norms_ref.norm(),
                 "weighted basis products V^* diag(d) X and column norms equal Eigen's");
    SI::Complex_dense_matrix B = SI::Complex_dense_matrix::Random(rows, 3);  // a d-orthonormal basis
    B.col(0) /= std::sqrt(B.col(0).cwiseAbs2().dot(d));
    for(Eigen::Index j = 1; j < 3; ++j)
    {
      for(int pass = 0; pass < 2; ++pass)
        B.col(j) -= B.leftCols(j) * (B.leftCols(j).adjoint() * d.asDiagonal() * B.col(j));
      B.col(j) /= std::sqrt(B.col(j).cwiseAbs2().dot(d));
    }
    for(Eigen::Index columns : {1, 2})
    {
      const SI::Complex_dense_matrix Q = SI::d_orthonormalize(d, B, X.leftCols(columns));
      const SI::Complex_dense_matrix gram = Q.adjoint() * d.asDiagonal() * Q, against = B.adjoint() * d.asDiagonal() * Q;
      const SI::Complex_dense_matrix span_error =  // X's columns lie in span(B, Q)
        X.leftCols(columns) - B * (B.adjoint() * d.asDiagonal() * X.leftCols(columns)) -
        Q * (Q.adjoint() * d.asDiagonal() * X.leftCols(columns));
      report.check(Q.cols() == columns &&
                     (gram - SI::Complex_dense_matrix::Identity(columns, columns)).norm() <= 1e-13 &&
                     against.norm() <= 1e-13 && span_error.norm() <= 1e-12 * X.leftCols(columns).norm(),
                   "d-orthonormalization of " + std::to_string(columns) +
                     " column(s) against a basis: orthonormal, orthogonal to it, same span");
    }
    report.check(SI::d_orthonormalize(d, B, B.col(1)).cols() == 0,
                 "d-orthonormalization drops a column inside the span of the basis");
  }

  Mesh sphere, torus, disk;
  make_icosphere(sphere, 3);
  make_torus(torus, 2., 0.7, 40, 20);
  make_disk(disk, 6);
  for(int n : {1, 2, 4, 7})
  {
    check_connection(report, "icosphere", sphere, n);
    check_connection(report, "torus", torus, n);
    check_connection(report, "disk", disk, n);
  }
  check_local_matrices_by_quadrature(report);
  check_index_sum_with_zero_coefficients(report, sphere);
  check_angle_reduction(report);
  {
    // A coarse torus with one edge collapsed across its 3 rings: the merged
    // vertex reaches a neighbour through two different edges.
    Mesh multiple;
    make_torus(multiple, 2., 0.7, 6, 3);
    CGAL::Euler::collapse_edge(multiple.edge(multiple.halfedge(Mesh::Vertex_index(0), Mesh::Vertex_index(1))), multiple);
    multiple.collect_garbage();
    report.check(CGAL::is_valid_polygon_mesh(multiple) && multiple.number_of_faces() == 34,
                 "the collapsed torus is a valid mesh of 34 faces");
    check_assembly_against_scatter(report, "torus with a multiple edge", multiple);
    check_assembly_against_scatter(report, "torus 40 x 20", torus);
    check_assembly_against_scatter(report, "disk", disk);
  }
  for(int n : {1, 3, 4})
    check_planar_cotan_laplacian(report, n);

  // Scaling the mesh by c leaves A unchanged and multiplies M by c^2.
  {
    Mesh big = torus;
    for(auto v : big.vertices()) big.point(v) = CGAL::ORIGIN + 1e3 * (big.point(v) - CGAL::ORIGIN);
    const SI::Indexed_mesh m1 = index_mesh(torus), m2 = index_mesh(big);
    const SI::Tangent_spaces t1 = SI::compute_tangent_spaces(m1), t2 = SI::compute_tangent_spaces(m2);
    const SI::Connection c1 = SI::compute_connection(m1, t1, 4), c2 = SI::compute_connection(m2, t2, 4);
    const SI::Components k1 = SI::split_into_components(m1), k2 = SI::split_into_components(m2);
    const SI::Energy_and_mass e1 = SI::assemble_energy_and_mass(m1, t1, c1, k1.list[0], k1.local_index, 0.5);
    const SI::Energy_and_mass e2 = SI::assemble_energy_and_mass(m2, t2, c2, k2.list[0], k2.local_index, 0.5);
    report.check(max_abs(e1.energy - e2.energy) < 1e-10 * max_abs(e1.energy), "A is scale invariant");
    report.check(max_abs(1e6 * e1.mass - e2.mass) < 1e-10 * max_abs(e2.mass), "M scales with the area");
  }

  for(const char* const* name = closed_shared_meshes(); *name; ++name)
  {
    const std::string path = shared_mesh_path(*name);
    if(path.empty()) continue;
    Mesh mesh;
    if(!report.check(CGAL::IO::read_polygon_mesh(path, mesh), std::string("read ") + *name)) continue;
    check_connection(report, *name, mesh, 4);
    if(mesh.number_of_vertices() <= 60000)
      for(int n : {1, 4})
        check_hermitian_and_psd(report, *name, mesh, n);
  }
  for(const char* const* name = open_shared_meshes(); *name; ++name)
  {
    const std::string path = shared_mesh_path(*name);
    if(path.empty()) continue;
    Mesh mesh;
    if(!report.check(CGAL::IO::read_polygon_mesh(path, mesh), std::string("read ") + *name)) continue;
    check_connection(report, *name, mesh, 4);
    for(int n : {1, 4})
      check_hermitian_and_psd(report, *name, mesh, n);
  }
  check_hermitian_and_psd(report, "disk", disk, 2);

  check_sphere_eigenvalues(report);
  return report.finish();
}
