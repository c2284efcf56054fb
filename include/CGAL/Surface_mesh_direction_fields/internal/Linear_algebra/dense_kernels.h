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

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <complex>
#include <cstddef>
#include <fstream>
#include <limits>
#include <mutex>
#include <thread>
#include <type_traits>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/resource.h>
#include <unistd.h>
#endif

// The four dense kernels of a supernodal Cholesky factorization (complex
// Hermitian rank-k update, product, triangular solve, dense Cholesky), in
// double or single precision, from the BLAS (through its standard C
// interface, CBLAS) and LAPACK linked at build time. The CMake target
// defines CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS and links both when it
// finds them (with CHOLMOD, which needs them too); without the macro the
// kernels are absent and CHOLMOD factors alone.
//
// LAPACK has no standard C header on every system (LAPACKE is a separate
// package): its Cholesky routines are declared here with the Fortran calling
// convention that CHOLMOD itself uses.
//
// Where the factorization's own threads work side by side (the independent
// subtrees of the elimination tree, whose supernodes are small), a
// multithreaded BLAS called from each of them at once makes them wait for
// each other (the developer notes). Two ways out:
// - by default the subtrees use the same kernels written with Eigen
//   (`Eigen_dense_kernels`), which always run on the calling thread, and
//   nothing outside the package changes;
// - where the user opted in (`set_openblas_thread_control()`, public header
//   openblas_thread_control.h) and OpenBLAS is linked with its thread control
//   (CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_OPENBLAS_THREADS, defined by the
//   CMake target), OpenBLAS is asked for one thread while the subtrees are
//   factored (`Single_threaded_blas`) and its previous number of threads is
//   given back afterwards. This is a process-wide setting: another thread of
//   the program that calls OpenBLAS during that phase runs it on one thread.
//   It is the faster of the two.
// The large supernodes at the top of the tree, factored one at a time, use
// the BLAS with its own threads in both cases.

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS
#include <cblas.h>
extern "C" {
void zpotrf_(const char* uplo, const int* n, std::complex<double>* a, const int* lda, int* info);
void cpotrf_(const char* uplo, const int* n, std::complex<float>* a, const int* lda, int* info);
}
#endif

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS
constexpr bool has_dense_kernels = true;
#else
constexpr bool has_dense_kernels = false;
#endif
#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS) && defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_OPENBLAS_THREADS)
constexpr bool can_control_blas_threads = true;
#else
constexpr bool can_control_blas_threads = false;
#endif

// The user's choice (openblas_thread_control.h): off until a program opts in.
inline std::atomic<bool>& openblas_thread_control_requested()
{
  static std::atomic<bool> requested(false);
  return requested;
}

// Whether the factorization sets OpenBLAS's number of threads now.
inline bool controls_blas_threads()
{
  return can_control_blas_threads && openblas_thread_control_requested().load();
}

// The address space the process may still map, read from its limit and its
// current size (/proc/self/statm) without mapping anything; the largest
// std::size_t where there is no limit, 0 where the size cannot be read.
inline std::size_t address_space_left()
{
#if defined(__unix__) || defined(__APPLE__)
  rlimit limit;
  if(getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return (std::numeric_limits<std::size_t>::max)();
  std::size_t pages = 0;
  std::ifstream statm("/proc/self/statm");
  if(!(statm >> pages)) return 0;
  const std::size_t in_use = pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t allowed = static_cast<std::size_t>(limit.rlim_cur);
  return allowed > in_use ? allowed - in_use : 0;
#else
  return (std::numeric_limits<std::size_t>::max)();
#endif
}

// Whether the BLAS can be called without a hang under memory pressure.
// OpenBLAS takes a work buffer for each calling thread the first time a
// level-3 routine runs there (128 MiB on x86-64 with Debian's 0.3.21), and
// when it cannot map it, it retries forever (both threads were seen looping
// in blas_memory_alloc under zpotrf_ with an address-space limit). So before
// a factorization, the package checks that the process's address-space limit
// leaves room for such buffers (160 MiB for each hardware thread and one
// more); where it does not, the factorization and its solves avoid the BLAS
// (Eigen's kernels, the package's solve), and a shortage shows as
// std::bad_alloc instead. The check only reads the limit and the process's
// size: nothing is mapped, so no other thread can see it.
// `extra_bytes` is counted beside it: what the caller is about to allocate
// before the BLAS runs (a distributed factor, for one).
inline bool blas_work_space_available(std::size_t extra_bytes = 0)
{
  const std::size_t threads = (std::max)(1u, std::thread::hardware_concurrency()) + 1;
  const std::size_t needed = threads * (std::size_t(160) << 20);
  const std::size_t left = address_space_left();
  return left >= needed && left - needed >= extra_bytes;
}

// For its lifetime, OpenBLAS runs on one thread (where the package controls
// it, see above; otherwise it does nothing). The scopes of concurrent
// factorizations are counted: the first saves OpenBLAS's number of threads,
// the last gives it back.
// Held by a factorization that calls the BLAS, for its whole length
// (supernodal_factorization.h): concurrent ones wait for each other.
inline std::mutex& blas_factorization_lock()
{
  static std::mutex m;
  return m;
}

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
#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS) && defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_OPENBLAS_THREADS)
    std::lock_guard<std::mutex> guard(lock());
    if(holders()++ == 0)
    {
      saved_threads() = openblas_get_num_threads();
      openblas_set_num_threads(1);
    }
#endif
  }
  ~Single_threaded_blas()
  {
#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS) && defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_OPENBLAS_THREADS)
    std::lock_guard<std::mutex> guard(lock());
    if(--holders() == 0) openblas_set_num_threads(saved_threads());
#endif
  }
  Single_threaded_blas(const Single_threaded_blas&) = delete;
  Single_threaded_blas& operator=(const Single_threaded_blas&) = delete;
};

// Column-major blocks of std::complex<Real> (Real: double or float), with
// leading dimensions.
template <typename Real>
struct Dense_kernels
{
  static_assert(std::is_same<Real, double>::value || std::is_same<Real, float>::value,
                "the BLAS has complex kernels in double and single precision only");
  typedef std::complex<Real> Scalar;
  static constexpr bool is_double = std::is_same<Real, double>::value;

  // the lower triangle of C (n x n) = A A^*, A being n x k
  static void lower_gram(int n, int k, const Scalar* A, int lda, Scalar* C, int ldc)
  {
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS
    if constexpr(is_double)
      cblas_zherk(CblasColMajor, CblasLower, CblasNoTrans, n, k, 1., A, lda, 0., C, ldc);
    else
      cblas_cherk(CblasColMajor, CblasLower, CblasNoTrans, n, k, 1.f, A, lda, 0.f, C, ldc);
#else
    (void)n, (void)k, (void)A, (void)lda, (void)C, (void)ldc;
#endif
  }

  // C (m x n) = A B^*, A being m x k and B n x k
  static void product_with_adjoint(int m, int n, int k, const Scalar* A, int lda, const Scalar* B, int ldb,
                                   Scalar* C, int ldc)
  {
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS
    const Scalar one(1), zero(0);
    if constexpr(is_double)
      cblas_zgemm(CblasColMajor, CblasNoTrans, CblasConjTrans, m, n, k, &one, A, lda, B, ldb, &zero, C, ldc);
    else
      cblas_cgemm(CblasColMajor, CblasNoTrans, CblasConjTrans, m, n, k, &one, A, lda, B, ldb, &zero, C, ldc);
#else
    (void)m, (void)n, (void)k, (void)A, (void)lda, (void)B, (void)ldb, (void)C, (void)ldc;
#endif
  }

  // B (m x n) := B L^-*, L being the lower triangle of an n x n block
  static void solve_with_adjoint_on_right(int m, int n, const Scalar* L, int ldl, Scalar* B, int ldb)
  {
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS
    const Scalar one(1);
    if constexpr(is_double)
      cblas_ztrsm(CblasColMajor, CblasRight, CblasLower, CblasConjTrans, CblasNonUnit, m, n, &one, L, ldl, B, ldb);
    else
      cblas_ctrsm(CblasColMajor, CblasRight, CblasLower, CblasConjTrans, CblasNonUnit, m, n, &one, L, ldl, B, ldb);
#else
    (void)m, (void)n, (void)L, (void)ldl, (void)B, (void)ldb;
#endif
  }

  // A = L L^* in place (the lower triangle of the n x n block A); returns
  // LAPACK's info: 0, or the 1-based column where A is not positive definite
  static int cholesky_lower(int n, Scalar* A, int lda)
  {
    int info = -1;
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS
    if constexpr(is_double)
      zpotrf_("L", &n, A, &lda, &info);
    else
      cpotrf_("L", &n, A, &lda, &info);
#else
    (void)n, (void)A, (void)lda;
#endif
    return info;
  }
};

// The kernels above with Eigen's dense products and Cholesky factorization,
// on the calling thread.
template <typename Real>
struct Eigen_dense_kernels
{
  typedef std::complex<Real> Scalar;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Dense;
  typedef Eigen::Map<Dense, 0, Eigen::OuterStride<> > Block;
  typedef Eigen::Map<const Dense, 0, Eigen::OuterStride<> > Const_block;

  static void lower_gram(int n, int k, const Scalar* A, int lda, Scalar* C, int ldc)
  {
    const Const_block a(A, n, k, Eigen::OuterStride<>(lda));
    Block c(C, n, n, Eigen::OuterStride<>(ldc));
    c.template triangularView<Eigen::Lower>().setZero();
    c.template selfadjointView<Eigen::Lower>().rankUpdate(a, Real(1));  // Eigen's Hermitian rank-k update
  }

  static void product_with_adjoint(int m, int n, int k, const Scalar* A, int lda, const Scalar* B, int ldb,
                                   Scalar* C, int ldc)
  {
    const Const_block a(A, m, k, Eigen::OuterStride<>(lda)), b(B, n, k, Eigen::OuterStride<>(ldb));
    Block c(C, m, n, Eigen::OuterStride<>(ldc));
    c.noalias() = a * b.adjoint();
  }

  static void solve_with_adjoint_on_right(int m, int n, const Scalar* L, int ldl, Scalar* B, int ldb)
  {
    const Const_block l(L, n, n, Eigen::OuterStride<>(ldl));
    Block b(B, m, n, Eigen::OuterStride<>(ldb));
    l.template triangularView<Eigen::Lower>().adjoint().template solveInPlace<Eigen::OnTheRight>(b);
  }

  // returns 0, or 1 where the block is not positive definite (Eigen does not
  // say in which column)
  static int cholesky_lower(int n, Scalar* A, int lda)
  {
    Block a(A, n, n, Eigen::OuterStride<>(lda));
    Eigen::LLT<Eigen::Ref<Dense, 0, Eigen::OuterStride<> >, Eigen::Lower> in_place(a);
    return in_place.info() == Eigen::Success ? 0 : 1;
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_DENSE_KERNELS_H
