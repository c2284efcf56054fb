// The smallest eigenpair of the pencil (A, M) of a mesh's largest component
// by SLEPc over the processes of mpirun, with the candidate methods of the
// distributed backend (issue: "Beyond one machine"):
//   krylov-schur  Krylov-Schur with shift-and-invert on a MUMPS LU factorization
//   lobpcg        LOBPCG preconditioned by PETSc's algebraic multigrid (GAMG), no factorization
// For each: the eigenvalue, the time, the iterations and the peak memory of
// every process. Every process assembles A and M with the package's own
// kernels and gives its row range to PETSc (the matrices are replicated; the
// solver's data are split).
//
//   mpirun -np K build/bin/benchmark_distributed_eigensolvers MESH [METHOD...]
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>

#include "largest_component.h"
#include "process_memory.h"

#include <slepceps.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SI = CGAL::Surface_mesh_direction_fields::internal;

namespace {

// The rows of this process of a whole (replicated) Hermitian matrix.
Mat distributed(const SI::Complex_sparse_matrix& S)
{
  const PetscInt n = static_cast<PetscInt>(S.rows());
  Mat A;
  MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n, n, 30, nullptr, 30, nullptr, &A);
  PetscInt first, last;
  MatGetOwnershipRange(A, &first, &last);
  for(Eigen::Index col = 0; col < S.outerSize(); ++col)
    for(SI::Complex_sparse_matrix::InnerIterator it(S, col); it; ++it)
      if(it.row() >= first && it.row() < last)
      {
        const PetscInt row = static_cast<PetscInt>(it.row()), c = static_cast<PetscInt>(col);
        const PetscScalar value = it.value();
        MatSetValues(A, 1, &row, 1, &c, &value, INSERT_VALUES);
      }
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  MatSetOption(A, MAT_HERMITIAN, PETSC_TRUE);
  return A;
}

// A + epsilon M, positive definite, with the near-null vector `near_null`
// (empty: none) for GAMG's aggregation.
Mat shifted_with_near_null_space(Mat A, Mat M, double epsilon, const SI::Complex_vector& near_null)
{
  Mat P;
  MatDuplicate(A, MAT_COPY_VALUES, &P);
  MatAXPY(P, epsilon, M, SAME_NONZERO_PATTERN);
  MatSetOption(P, MAT_HERMITIAN, PETSC_TRUE);
  if(near_null.size() > 0)
  {
    Vec v;
    MatCreateVecs(P, &v, nullptr);
    PetscInt first, last;
    VecGetOwnershipRange(v, &first, &last);
    PetscScalar* values;
    VecGetArray(v, &values);
    for(PetscInt i = first; i < last; ++i) values[i - first] = near_null[static_cast<Eigen::Index>(i)];
    VecRestoreArray(v, &values);
    VecNormalize(v, nullptr);
    MatNullSpace space;
    MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, 1, &v, &space);
    MatSetNearNullSpace(P, space);
    MatNullSpaceDestroy(&space);
    VecDestroy(&v);
  }
  return P;
}

void configure(EPS eps, const std::string& method, Mat P, double epsilon)
{
  ST st;
  KSP ksp;
  PC pc;
  EPSGetST(eps, &st);
  STGetKSP(st, &ksp);
  KSPGetPC(ksp, &pc);
  if(method.rfind("ks-cg-gamg", 0) == 0)  // inexact shift-and-invert: CG on A + epsilon M
  {
    EPSSetType(eps, EPSKRYLOVSCHUR);
    EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE);
    EPSSetTarget(eps, -epsilon);
    STSetType(st, STSINVERT);
    STSetPreconditionerMat(st, P);
    KSPSetType(ksp, KSPCG);
    KSPSetTolerances(ksp, 1e-12, PETSC_DEFAULT, PETSC_DEFAULT, 10000);
    PCSetType(pc, PCGAMG);
  }
  else if(method.rfind("lobpcg-gamg", 0) == 0)
  {
    EPSSetType(eps, EPSLOBPCG);
    EPSSetWhichEigenpairs(eps, EPS_SMALLEST_REAL);
    STSetType(st, STPRECOND);
    STSetPreconditionerMat(st, P);
    KSPSetType(ksp, KSPPREONLY);
    PCSetType(pc, PCGAMG);
  }
  else if(method == "krylov-schur")
  {
    EPSSetType(eps, EPSKRYLOVSCHUR);
    EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE);
    EPSSetTarget(eps, 0.);
    STSetType(st, STSINVERT);
    KSPSetType(ksp, KSPPREONLY);
    PCSetType(pc, PCLU);
    PCFactorSetMatSolverType(pc, MATSOLVERMUMPS);
  }
  else  // lobpcg
  {
    EPSSetType(eps, EPSLOBPCG);
    EPSSetWhichEigenpairs(eps, EPS_SMALLEST_REAL);
    STSetType(st, STPRECOND);
    KSPSetType(ksp, KSPPREONLY);
    PCSetType(pc, PCGAMG);
  }
}

} // namespace

int main(int argc, char** argv)
{
  SlepcInitialize(&argc, &argv, nullptr, nullptr);
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  {
    Mesh mesh;
    if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
    {
      if(rank == 0) std::cerr << "usage: benchmark_distributed_eigensolvers MESH [krylov-schur] [lobpcg]\n";
      SlepcFinalize();
      return 1;
    }
    std::vector<std::string> methods;
    for(int i = 2; i < argc; ++i)
      if(argv[i][0] != '-') methods.push_back(argv[i]);
    if(methods.empty()) methods = {"krylov-schur", "lobpcg"};
    const SI::Energy_and_mass em = Largest_component<Mesh>(mesh).matrices(0.);
    const double epsilon = 1e-8 * SI::eigenvalue_scale(em.energy, em.mass);
    for(const std::string& method : methods)
    {
      const auto start = std::chrono::steady_clock::now();
      // "-gauge" methods: the unknowns are rotated by the phases of the
      // package's coarse estimate b of the eigenvector (A' = D^* A D with
      // D = diag(b_i / |b_i|)), so that the real vector |b| is a near-null
      // vector of A' and GAMG's prolongation stays real: PETSc's multigrid
      // restricts with the transpose, not the adjoint, so a complex
      // prolongation would make the preconditioner non-Hermitian.
      const bool gauge = method.size() > 6 && method.compare(method.size() - 6, 6, "-gauge") == 0;
      SI::Complex_vector estimate, phase, modulus;
      SI::Complex_sparse_matrix energy = em.energy, mass = em.mass;
      if(gauge)
      {
        SI::Eigen_solve_options options;
        estimate = SI::coarse_estimate<CGAL::Surface_mesh_direction_fields::Default_direction_field_solver>(
                     em.energy, em.mass, true, options).vector;
        phase = estimate.unaryExpr([](const SI::Complex& z) { return SI::unit(z); });
        modulus = estimate.cwiseAbs().cast<SI::Complex>();
        for(SI::Complex_sparse_matrix* S : {&energy, &mass})
          for(Eigen::Index col = 0; col < S->outerSize(); ++col)
            for(SI::Complex_sparse_matrix::InnerIterator it(*S, col); it; ++it)
              it.valueRef() *= std::conj(phase[it.row()]) * phase[col];
      }
      Mat A = distributed(energy), M = distributed(mass);
      EPS eps;
      EPSCreate(PETSC_COMM_WORLD, &eps);
      EPSSetOperators(eps, A, M);
      EPSSetProblemType(eps, EPS_GHEP);
      EPSSetDimensions(eps, 1, PETSC_DEFAULT, PETSC_DEFAULT);
      EPSSetTolerances(eps, 1e-10, 1000);
      Mat P = shifted_with_near_null_space(A, M, epsilon, modulus);
      configure(eps, method, P, epsilon);
      if(gauge)
      {
        Vec v;
        MatCreateVecs(A, &v, nullptr);
        PetscInt first, last;
        VecGetOwnershipRange(v, &first, &last);
        for(PetscInt i = first; i < last; ++i) VecSetValue(v, i, modulus[static_cast<Eigen::Index>(i)], INSERT_VALUES);
        VecAssemblyBegin(v);
        VecAssemblyEnd(v);
        EPSSetInitialSpace(eps, 1, &v);
        VecDestroy(&v);
      }
      EPSSetFromOptions(eps);
      EPSSolve(eps);
      PetscInt converged = 0, iterations = 0;
      EPSGetConverged(eps, &converged);
      EPSGetIterationNumber(eps, &iterations);
      PetscScalar lambda = 0.;
      if(converged > 0) EPSGetEigenpair(eps, 0, &lambda, nullptr, nullptr, nullptr);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      EPSDestroy(&eps);
      MatDestroy(&P);
      MatDestroy(&A);
      MatDestroy(&M);
      std::vector<double> peaks(static_cast<std::size_t>(size));
      const double peak = proc_status_mb("VmHWM:");
      MPI_Gather(&peak, 1, MPI_DOUBLE, peaks.data(), 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
      if(rank == 0)
      {
        std::printf("%-13s ranks %d  vertices %ld  eigenvalue %.15g  converged %ld  iterations %ld  %.0f ms  peak MB",
                    method.c_str(), size, static_cast<long>(em.energy.rows()), PetscRealPart(lambda),
                    static_cast<long>(converged), static_cast<long>(iterations), ms);
        for(double p : peaks) std::printf(" %.0f", p);
        std::printf("\n");
      }
    }
  }
  SlepcFinalize();
  return 0;
}
