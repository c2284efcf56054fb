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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_PETSC_CALLS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_PETSC_CALLS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <petscsys.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <stdexcept>

// Every PETSc, SLEPc and MPI call of the distributed solvers goes through
// one of the two macros below. The processes of a distributed solve take
// part in the same collective calls: once one of them has failed, the
// others would wait for it forever, and no error can be agreed on any more.
// So the failing process prints one line on stderr (its rank, the call, and
// PETSc's or MPI's message) and ends every process of the run with
// MPI_Abort, PETSc's own way out of a failed collective (PetscCallAbort does
// the same after printing PETSc's trace). A program that wants the one line
// only, and not also PETSc's trace from inside the failing routine, pushes
// Petsc_distributed_solver::error_handler after initializing PETSc (direction_field does).

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

// Where an error arose in PETSc (the routine and its message), which PETSc
// passes to the error handler only. Recorded by record_petsc_error when a
// program pushes it as PETSc's error handler
// (Petsc_distributed_solver::error_handler).
struct Petsc_initial_error
{
  char routine[64] = "";
  char message[192] = "";
};

inline Petsc_initial_error& petsc_initial_error()
{
  static thread_local Petsc_initial_error error;
  return error;
}

inline PetscErrorCode record_petsc_error(MPI_Comm, int, const char* routine, const char*, PetscErrorCode code,
                                         PetscErrorType type, const char* message, void*)
{
  if(type == PETSC_ERROR_INITIAL)
  {
    Petsc_initial_error& e = petsc_initial_error();
    std::snprintf(e.routine, sizeof(e.routine), "%s", routine != nullptr ? routine : "");
    std::snprintf(e.message, sizeof(e.message), "%s", message != nullptr ? message : "");
  }
  return code;
}

[[noreturn]] inline void abort_after_petsc_error(PetscErrorCode code, const char* call)
{
  // PETSc's message for the error code; a failed allocation inside PETSc
  // (its error arose in PetscMalloc...) may come with a code of no message
  const char* message = nullptr;
  if(PetscErrorMessage(code, &message, nullptr) != 0) message = nullptr;
  const Petsc_initial_error& initial = petsc_initial_error();
  char text[320];
  if(code == PETSC_ERR_MEM || std::strncmp(initial.routine, "PetscMalloc", 11) == 0)
    std::snprintf(text, sizeof(text), "out of memory");
  else if(message != nullptr && initial.message[0] != '\0')
    std::snprintf(text, sizeof(text), "%s (%s)", message, initial.message);
  else if(message != nullptr)
    std::snprintf(text, sizeof(text), "%s", message);
  else
    std::snprintf(text, sizeof(text), "PETSc error %d%s%s", static_cast<int>(code), initial.message[0] ? ": " : "",
                  initial.message);
  print_failed_call("PETSc", call, text);
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

// Runs one step of a collective request (`step` names it, e.g. "the
// eigen-solve"). Once a process has entered a collective request, the others
// wait for it inside PETSc or MPI: an exception on one process (out of
// memory, or any other) cannot be agreed on, so it ends every process too,
// after the failing process's one line.
template <typename Step>
auto run_collective_step(const char* step, Step&& run) -> decltype(run())
{
  const char* failure = nullptr;
  try
  {
    return run();
  }
  catch(const std::bad_alloc&)
  {
    failure = "out of memory";
  }
  catch(const std::length_error&)  // a size beyond what a container can hold
  {
    failure = "out of memory";
  }
  catch(const std::exception& e)
  {
    failure = e.what();
  }
  int rank = -1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::fprintf(stderr, "Surface_mesh_direction_fields: error on process %d: %s in %s\n", rank, failure, step);
  std::fflush(stderr);
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

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_PETSC_CALLS_H
