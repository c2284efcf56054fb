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

#if defined(__unix__) || defined(__APPLE__)
#include <dlfcn.h>
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_HAS_DLSYM 1
#endif

// The four dense kernels of a supernodal Cholesky factorization (complex
// Hermitian rank-k update, product, triangular solve, dense Cholesky), taken
// from the BLAS and LAPACK the process already has loaded: CHOLMOD calls
// them, so linking CHOLMOD is all a user of the package does. They are looked
// up by name at run time (32-bit integer interface, Fortran names); where
// the lookup fails (no dynamic loader, a static build, another naming), the
// kernels are missing and the caller uses CHOLMOD's own factorization.
//
// OpenBLAS runs large calls on its own threads; when two of the package's
// threads call it at once, those calls wait for each other. While independent
// subtrees are factored on the package's threads, OpenBLAS is therefore asked
// for one thread (`Single_threaded_blas`), and given its previous number back
// afterwards. Other BLAS libraries are left as they are.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Dense_kernels
{
  typedef std::complex<double> Complex;
  typedef void (*Herk)(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha,
                       const Complex* a, const int* lda, const double* beta, Complex* c, const int* ldc);
  typedef void (*Gemm)(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const Complex* alpha, const Complex* a, const int* lda, const Complex* b, const int* ldb,
                       const Complex* beta, Complex* c, const int* ldc);
  typedef void (*Trsm)(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
                       const int* n, const Complex* alpha, const Complex* a, const int* lda, Complex* b,
                       const int* ldb);
  typedef void (*Potrf)(const char* uplo, const int* n, Complex* a, const int* lda, int* info);
  typedef void (*Set_threads)(int);
  typedef int (*Get_threads)();

  Herk herk = nullptr;
  Gemm gemm = nullptr;
  Trsm trsm = nullptr;
  Potrf potrf = nullptr;
  Set_threads set_threads = nullptr;  // OpenBLAS only
  Get_threads get_threads = nullptr;

  bool complete() const { return herk && gemm && trsm && potrf; }
};

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HAS_DLSYM
template <typename Function>
Function loaded_function(const char* name)
{
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}
#endif

// The kernels of this process, looked up once.
inline const Dense_kernels& dense_kernels()
{
  static const Dense_kernels kernels = [] {
    Dense_kernels k;
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HAS_DLSYM
    k.herk = loaded_function<Dense_kernels::Herk>("zherk_");
    k.gemm = loaded_function<Dense_kernels::Gemm>("zgemm_");
    k.trsm = loaded_function<Dense_kernels::Trsm>("ztrsm_");
    k.potrf = loaded_function<Dense_kernels::Potrf>("zpotrf_");
    k.set_threads = loaded_function<Dense_kernels::Set_threads>("openblas_set_num_threads");
    k.get_threads = loaded_function<Dense_kernels::Get_threads>("openblas_get_num_threads");
    if(!k.set_threads || !k.get_threads) k.set_threads = nullptr, k.get_threads = nullptr;
#endif
    return k;
  }();
  return kernels;
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
    const Dense_kernels& k = dense_kernels();
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
    const Dense_kernels& k = dense_kernels();
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
