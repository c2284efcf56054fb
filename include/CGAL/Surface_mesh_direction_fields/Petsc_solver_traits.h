// Copyright (c) 2026  The Surface_mesh_direction_fields authors.
// All rights reserved.
//
// This file is part of CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s)     : The Surface_mesh_direction_fields authors

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_PETSC_SOLVER_TRAITS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_PETSC_SOLVER_TRAITS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/petsc_calls.h>

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_vector.h>

#include <petscksp.h>

#include <complex>
#include <memory>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

A sparse solver that factors over several processes: a model of
`SparseLinearAlgebraWithFactorTraits_d` (with `std::complex<double>` as `NT`)
whose factorization is a distributed LU factorization by MUMPS through PETSc
(Debian packages `libpetsc-complex-dev`, `openmpi-bin`), for the class
`Globally_optimal_direction_field` (its `SparseSolver` parameter) or the named
parameter `sparse_linear_solver`.

Every process of `communicator` runs the same computation on the same mesh
(the mesh, the matrices and the vectors of the eigen-solve are on every
process); the factorization, the largest part of the memory and of the time on
large meshes, is split over the processes: each one holds the rows of its
range. A solve sends each process its rows of the right-hand side and gathers
the solution on all. PETSc must be initialized (`PetscInitialize()`) before
the first factorization and finalized after the last object of this class is
destroyed.

MUMPS's Cholesky factorization is for complex symmetric, not Hermitian,
matrices, so the Hermitian matrices of the method are factored by LU: this
solver cannot tell a matrix that is not positive definite (the package checks
with the smallest eigenvalue instead, as for any solver of the concept).
*/
class Petsc_solver_traits
{
public:
  /// the scalar type
  typedef std::complex<double> NT;
  /// the matrix type (the same on every process)
  typedef CGAL::Eigen_sparse_matrix<NT> Matrix;
  /// the vector type (the same on every process)
  typedef CGAL::Eigen_vector<NT> Vector;

  /// a solver over the processes of `communicator`
  /// \param communicator the processes that share the factorizations
  explicit Petsc_solver_traits(MPI_Comm communicator = PETSC_COMM_WORLD) : m_state(new State(communicator)) {}

  /// a new solver on the same communicator (a factorization is never shared)
  /// \param other the solver whose communicator is taken
  Petsc_solver_traits(const Petsc_solver_traits& other) : m_state(new State(other.m_state->comm)) {}

  /// a new solver on the communicator of `other` (a factorization is never shared)
  /// \param other the solver whose communicator is taken
  /// \returns this solver
  Petsc_solver_traits& operator=(const Petsc_solver_traits& other)
  {
    if(this != &other) m_state.reset(new State(other.m_state->comm));
    return *this;
  }

  /// factors `A` (which every process passes whole)
  /// \param A the matrix
  /// \param D set to 1
  /// \returns whether the factorization succeeded
  bool factor(const Matrix& A, NT& D)
  {
    D = NT(1);
    return m_state->factor(A.eigen_object());
  }

  /// solves `A X = B` with the last factorization
  /// \param B the right-hand side, whole on every process
  /// \param X the solution, whole on every process
  /// \returns whether the solve succeeded
  bool linear_solver(const Vector& B, Vector& X) { return m_state->solve(B, X); }

  /// factors `A` and solves `A X = B`
  /// \param A the matrix
  /// \param B the right-hand side
  /// \param X the solution
  /// \param D set to 1
  /// \returns whether both succeeded
  bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D)
  {
    return factor(A, D) && linear_solver(B, X);
  }

  /// the number of processes of the communicator
  /// \returns that number
  int number_of_processes() const { return m_state->size; }

private:
  // The PETSc objects of one factorization.
  struct State
  {
    MPI_Comm comm;
    int size = 1, rank = 0;
    Mat A = nullptr;
    KSP ksp = nullptr;
    Vec b = nullptr, x = nullptr, all = nullptr;
    VecScatter to_all = nullptr;
    PetscInt first = 0, last = 0;

    explicit State(MPI_Comm c) : comm(c)
    {
      CGAL_SMDF_MPI_CALL(MPI_Comm_size(comm, &size));
      CGAL_SMDF_MPI_CALL(MPI_Comm_rank(comm, &rank));
    }
    ~State() { clear(); }

    void clear()
    {
      if(to_all) CGAL_SMDF_PETSC_CALL(VecScatterDestroy(&to_all));
      if(all) CGAL_SMDF_PETSC_CALL(VecDestroy(&all));
      if(x) CGAL_SMDF_PETSC_CALL(VecDestroy(&x));
      if(b) CGAL_SMDF_PETSC_CALL(VecDestroy(&b));
      if(ksp) CGAL_SMDF_PETSC_CALL(KSPDestroy(&ksp));
      if(A) CGAL_SMDF_PETSC_CALL(MatDestroy(&A));
    }

    // The rows [first, last) of this process, from the whole column-major matrix.
    bool assemble(const Eigen::SparseMatrix<NT>& S)
    {
      const PetscInt n = static_cast<PetscInt>(S.rows());
      PetscInt local = PETSC_DECIDE, global = n;
      if(PetscSplitOwnership(comm, &local, &global) != 0) return false;
      CGAL_SMDF_MPI_CALL(MPI_Scan(&local, &last, 1, MPIU_INT, MPI_SUM, comm));
      first = last - local;
      // the entries of each of this process's rows (column-major input: scan every column)
      std::vector<std::vector<std::pair<PetscInt, NT> > > rows(static_cast<std::size_t>(local));
      for(Eigen::Index col = 0; col < S.outerSize(); ++col)
        for(Eigen::SparseMatrix<NT>::InnerIterator it(S, col); it; ++it)
          if(it.row() >= first && it.row() < last)
            rows[static_cast<std::size_t>(it.row() - first)].emplace_back(static_cast<PetscInt>(col), it.value());
      std::vector<PetscInt> diagonal(static_cast<std::size_t>(local)), off(static_cast<std::size_t>(local));
      for(PetscInt r = 0; r < local; ++r)
        for(const auto& e : rows[static_cast<std::size_t>(r)])
          ++(e.first >= first && e.first < last ? diagonal : off)[static_cast<std::size_t>(r)];
      if(MatCreateAIJ(comm, local, local, n, n, 0, diagonal.data(), 0, off.data(), &A) != 0) return false;
      for(PetscInt r = 0; r < local; ++r)
        for(const auto& e : rows[static_cast<std::size_t>(r)])
        {
          const PetscInt row = first + r, col = e.first;
          const PetscScalar value = e.second;
          CGAL_SMDF_PETSC_CALL(MatSetValues(A, 1, &row, 1, &col, &value, INSERT_VALUES));
        }
      return MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY) == 0 && MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY) == 0;
    }

    bool factor(const Eigen::SparseMatrix<NT>& S)
    {
      clear();
      if(!assemble(S)) return false;
      PC pc;
      if(KSPCreate(comm, &ksp) != 0 || KSPSetOperators(ksp, A, A) != 0 || KSPSetType(ksp, KSPPREONLY) != 0 ||
         KSPGetPC(ksp, &pc) != 0 || PCSetType(pc, PCLU) != 0 || PCFactorSetMatSolverType(pc, MATSOLVERMUMPS) != 0 ||
         KSPSetErrorIfNotConverged(ksp, PETSC_TRUE) != 0 || KSPSetFromOptions(ksp) != 0 || KSPSetUp(ksp) != 0)
        return false;
      return MatCreateVecs(A, &x, &b) == 0 && VecScatterCreateToAll(x, &to_all, &all) == 0;
    }

    bool solve(const Vector& B, Vector& X)
    {
      if(ksp == nullptr) return false;
      PetscScalar* values;
      CGAL_SMDF_PETSC_CALL(VecGetArray(b, &values));
      for(PetscInt i = first; i < last; ++i) values[i - first] = B[static_cast<int>(i)];
      CGAL_SMDF_PETSC_CALL(VecRestoreArray(b, &values));
      if(KSPSolve(ksp, b, x) != 0) return false;
      CGAL_SMDF_PETSC_CALL(VecScatterBegin(to_all, x, all, INSERT_VALUES, SCATTER_FORWARD));
      CGAL_SMDF_PETSC_CALL(VecScatterEnd(to_all, x, all, INSERT_VALUES, SCATTER_FORWARD));
      const PetscScalar* result;
      CGAL_SMDF_PETSC_CALL(VecGetArrayRead(all, &result));
      for(int i = 0; i < X.size(); ++i) X[i] = result[i];
      CGAL_SMDF_PETSC_CALL(VecRestoreArrayRead(all, &result));
      return true;
    }
  };

  std::unique_ptr<State> m_state;
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_PETSC_SOLVER_TRAITS_H
