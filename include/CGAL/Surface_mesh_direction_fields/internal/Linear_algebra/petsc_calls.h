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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_PETSC_CALLS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_PETSC_CALLS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <petscsys.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

// Every PETSc, SLEPc and MPI call of the distributed solvers goes through
// one of the two macros below. The processes of a distributed solve take
// part in the same collective calls: once one of them has failed, the
// others would wait for it forever, and no error can be agreed on any more.
// So the failing process prints one line on stderr (its rank, the call, and
// PETSc's or MPI's message) and ends every process of the run with
// MPI_Abort, PETSc's own way out of a failed collective (PetscCallAbort does
// the same after printing PETSc's trace). A program that wants the one line
// only, and not also PETSc's trace from inside the failing routine, pushes
// PetscReturnErrorHandler after initializing PETSc (direction_field does).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// the name of the routine called in `call` (the text up to its parenthesis)
inline void print_failed_call(const char* library, const char* call, const char* message)
{
  int rank = -1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::size_t name_length = std::strcspn(call, "( ");
  std::fprintf(stderr, "Surface_mesh_direction_fields: error on process %d: %s failed in %.*s: %s\n", rank, library,
               static_cast<int>(name_length), call, message);
  std::fflush(stderr);
}

[[noreturn]] inline void abort_after_petsc_error(PetscErrorCode code, const char* call)
{
  const char* message = nullptr;
  if(PetscErrorMessage(code, &message, nullptr) != 0 || message == nullptr) message = "unknown error";
  print_failed_call("PETSc", call, message);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();  // MPI_Abort does not return
}

[[noreturn]] inline void abort_after_mpi_error(int code, const char* call)
{
  char message[MPI_MAX_ERROR_STRING] = "unknown error";
  int length = 0;
  MPI_Error_string(code, message, &length);
  print_failed_call("MPI", call, message);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

// a call of PETSc or SLEPc, returning a PetscErrorCode
#define CGAL_SMDF_PETSC_CALL(...)                                                                   \
  do                                                                                                \
  {                                                                                                 \
    const PetscErrorCode cgal_smdf_code_ = (__VA_ARGS__);                                           \
    if(PetscUnlikely(cgal_smdf_code_ != 0))                                                         \
      ::CGAL::Surface_mesh_direction_fields::internal::abort_after_petsc_error(cgal_smdf_code_, #__VA_ARGS__); \
  } while(false)

// a call of MPI, returning an MPI error code
#define CGAL_SMDF_MPI_CALL(...)                                                                     \
  do                                                                                                \
  {                                                                                                 \
    const int cgal_smdf_code_ = (__VA_ARGS__);                                                      \
    if(PetscUnlikely(cgal_smdf_code_ != MPI_SUCCESS))                                               \
      ::CGAL::Surface_mesh_direction_fields::internal::abort_after_mpi_error(cgal_smdf_code_, #__VA_ARGS__); \
  } while(false)

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_PETSC_CALLS_H
