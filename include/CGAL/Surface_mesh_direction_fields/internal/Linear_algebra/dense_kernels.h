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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_DENSE_KERNELS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_DENSE_KERNELS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <complex>
#include <mutex>
#include <type_traits>

#if defined(__unix__) || defined(__APPLE__)
#include <dlfcn.h>
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_HAS_DLSYM 1
#endif

// The four dense kernels of a supernodal Cholesky factorization (complex
// Hermitian rank-k update, product, triangular solve, dense Cholesky), in
// double (zherk, ...) or single precision (cherk, ...), taken from the BLAS
// and LAPACK the process already has loaded: CHOLMOD calls them, so linking
// CHOLMOD is all a user of the package does. They are looked up by name at
// run time (32-bit integer interface, Fortran names); where the lookup fails
// (no dynamic loader, a static build, another naming), the kernels are
// missing and the caller uses CHOLMOD's own factorization.
//
// OpenBLAS runs large calls on its own threads; when two of the package's
// threads call it at once, those calls wait for each other. While independent
// subtrees are factored on the package's threads, OpenBLAS is therefore asked
// for one thread (`Single_threaded_blas`), and given its previous number back
// afterwards. Other BLAS libraries are left as they are.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename Real>
struct Dense_kernels
{
  typedef std::complex<Real> Scalar;
  typedef void (*Herk)(const char* uplo, const char* trans, const int* n, const int* k, const Real* alpha,
                       const Scalar* a, const int* lda, const Real* beta, Scalar* c, const int* ldc);
  typedef void (*Gemm)(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const Scalar* alpha, const Scalar* a, const int* lda, const Scalar* b, const int* ldb,
                       const Scalar* beta, Scalar* c, const int* ldc);
  typedef void (*Trsm)(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
                       const int* n, const Scalar* alpha, const Scalar* a, const int* lda, Scalar* b,
                       const int* ldb);
  typedef void (*Potrf)(const char* uplo, const int* n, Scalar* a, const int* lda, int* info);

  Herk herk = nullptr;
  Gemm gemm = nullptr;
  Trsm trsm = nullptr;
  Potrf potrf = nullptr;

  bool complete() const { return herk && gemm && trsm && potrf; }
};

// OpenBLAS's control of its threads (absent from other BLAS libraries).
struct Blas_thread_control
{
  typedef void (*Set_threads)(int);
  typedef int (*Get_threads)();
  Set_threads set_threads = nullptr;
  Get_threads get_threads = nullptr;
};

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HAS_DLSYM
template <typename Function>
Function loaded_function(const char* name)
{
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}
#endif

// The kernels of this process for complex<Real> (Real: double or float),
// looked up once.
template <typename Real>
const Dense_kernels<Real>& dense_kernels()
{
  static_assert(std::is_same<Real, double>::value || std::is_same<Real, float>::value,
                "the BLAS has complex kernels in double and single precision only");
  static const Dense_kernels<Real> kernels = [] {
    Dense_kernels<Real> k;
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HAS_DLSYM
    const bool single = std::is_same<Real, float>::value;
    typedef Dense_kernels<Real> K;
    k.herk = loaded_function<typename K::Herk>(single ? "cherk_" : "zherk_");
    k.gemm = loaded_function<typename K::Gemm>(single ? "cgemm_" : "zgemm_");
    k.trsm = loaded_function<typename K::Trsm>(single ? "ctrsm_" : "ztrsm_");
    k.potrf = loaded_function<typename K::Potrf>(single ? "cpotrf_" : "zpotrf_");
#endif
    return k;
  }();
  return kernels;
}

inline const Blas_thread_control& blas_thread_control()
{
  static const Blas_thread_control control = [] {
    Blas_thread_control c;
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HAS_DLSYM
    c.set_threads = loaded_function<Blas_thread_control::Set_threads>("openblas_set_num_threads");
    c.get_threads = loaded_function<Blas_thread_control::Get_threads>("openblas_get_num_threads");
    if(!c.set_threads || !c.get_threads) c.set_threads = nullptr, c.get_threads = nullptr;
#endif
    return c;
  }();
  return control;
}

// For its lifetime, OpenBLAS uses one thread. The scopes of concurrent
// factorizations are counted: the first saves the number of threads, the
// last restores it.
class Single_threaded_blas
{
  static std::mutex& lock()
  {
    static std::mutex m;
    return m;
  }
  static int& holders()
  {
    static int count = 0;
    return count;
  }
  static int& saved_threads()
  {
    static int threads = 1;
    return threads;
  }

public:
  Single_threaded_blas()
  {
    const Blas_thread_control& k = blas_thread_control();
    if(!k.set_threads) return;
    std::lock_guard<std::mutex> guard(lock());
    if(holders()++ == 0)
    {
      saved_threads() = k.get_threads();
      k.set_threads(1);
    }
  }
  ~Single_threaded_blas()
  {
    const Blas_thread_control& k = blas_thread_control();
    if(!k.set_threads) return;
    std::lock_guard<std::mutex> guard(lock());
    if(--holders() == 0) k.set_threads(saved_threads());
  }
  Single_threaded_blas(const Single_threaded_blas&) = delete;
  Single_threaded_blas& operator=(const Single_threaded_blas&) = delete;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_DENSE_KERNELS_H
