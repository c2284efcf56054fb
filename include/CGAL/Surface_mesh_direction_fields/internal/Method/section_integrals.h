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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SECTION_INTEGRALS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SECTION_INTEGRALS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <array>
#include <cmath>
#include <complex>

// The scalar kernels of the local (per-triangle) matrices: integrals of products
// of piecewise-linear basis sections over a triangle carrying holonomy `Omega`
// (user manual, section "Energies"). No mesh here, only functions of one real number.
//
// All three kernels have the form  F(x) = P(x, e^{ix}) / x^4  whose numerator
// cancels to order x^4 (resp. x^5) at x = 0, so the closed forms lose up to
// 4 * log10(1/|x|) digits. Writing z = ix, each one is a power series
//     F(x) = sum_k c_k z^k
// with real coefficients c_k obtained by expanding e^z in the closed form
// (the polynomial part cancels the first terms). Near 0 we sum that series;
// away from 0 the closed form has no cancellation worth speaking of. Both
// branches are accurate to a few ulps; the test compares them to a
// 150-digit reference on [-6 pi, 6 pi].

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Below this |x| the series is summed, above it the closed form is used.
// At |x| = 2 the series terms decay like 2^k k^2 / (k+4)! (no growth, little
// cancellation), and the closed form's numerator is no longer dominated by
// the terms that cancel.
constexpr double section_integral_series_threshold = 2.;
constexpr int section_integral_series_terms = 32;  // 2^32 / 36! < 1e-31

struct Section_integral_series
{
  // c[k] for the mass factor, f1 and f2; see the derivation in each function.
  std::array<double, section_integral_series_terms> mass, f1, f2;

  Section_integral_series()
  {
    double factorial = 24.;  // m! with m = k + 4, starting at 4! = 24
    for(int k = 0; k < section_integral_series_terms; ++k)
    {
      const double m = k + 4;
      if(k > 0)
        factorial *= m;
      // mass:  (6e^z - 6 - 6z - 3z^2 - z^3) / (3 z^4) = 2 sum_{m>=4} z^{m-4} / m!
      mass[k] = 2. / factorial;
      // f1: numerator 3 + z + z^4/24 - z^5/60 + (-3 + 2z - z^2/2) e^z;
      // the coefficient of z^m in the product is (-3 + 2m - m(m-1)/2) / m!.
      f1[k] = (-3. + 2. * m - m * (m - 1.) / 2.) / factorial;
      // f2: numerator 4 + z + z^3/6 - z^4/12 + z^5/30 + (-4 + 3z - z^2) e^z;
      // the coefficient of z^m in the product is (-4 + 3m - m(m-1)) / m!.
      f2[k] = (-4. + 3. * m - m * (m - 1.)) / factorial;
    }
    // Add the polynomial parts of the numerators (terms z^4 and z^5).
    f1[0] += 1. / 24.;   // -> 0
    f1[1] += -1. / 60.;  // -> -1/24
    f2[0] += -1. / 12.;  // -> -1/4
    f2[1] += 1. / 30.;   // -> -1/24
    f1[0] = 0.;          // exact cancellation, avoid a rounding residue
  }

  static const Section_integral_series& get()
  {
    static const Section_integral_series series;
    return series;
  }
};

// sum_k c[k] (ix)^k, real and imaginary parts summed separately by Horner's
// rule in x^2: Re = sum_j c[2j] (-x^2)^j, Im = x sum_j c[2j+1] (-x^2)^j.
inline std::complex<double>
sum_series_in_ix(const std::array<double, section_integral_series_terms>& c, double x)
{
  const double minus_x2 = -x * x;
  double re = 0., im = 0.;
  for(int j = section_integral_series_terms / 2 - 1; j >= 0; --j)
  {
    re = re * minus_x2 + c[2 * j];
    im = im * minus_x2 + c[2 * j + 1];
  }
  return std::complex<double>(re, x * im);
}

inline bool use_series(double x) { return std::abs(x) < section_integral_series_threshold; }

// A kernel at x: its Taylor series near 0, where the closed form loses its
// digits, else closed_form(e^{ix}, x^2).
template <typename ClosedForm>
std::complex<double> series_or_closed_form(const std::array<double, section_integral_series_terms>& series, double x,
                                           const ClosedForm& closed_form)
{
  if(use_series(x)) return sum_series_in_ix(series, x);
  return closed_form(std::polar(1., x), x * x);
}

/// Mass kernel: the off-diagonal local mass entry is `r_jk |t| mass_factor(Omega)`.
/// `mass_factor(x) = (6 e^{ix} - 6 - 6ix + 3x^2 + ix^3) / (3 x^4)`, equal to 1/12 at 0.
inline std::complex<double> mass_factor(double x)
{
  return series_or_closed_form(Section_integral_series::get().mass, x, [x](std::complex<double> e, double x2) {
    const std::complex<double> I(0., 1.);
    return (6. * e - 6. - 6. * I * x + 3. * x2 + I * (x2 * x)) / (3. * x2 * x2);
  });
}

/// Dirichlet kernel multiplying `|p_ij|^2 + |p_ik|^2`; `f1(0) = 0`.
inline std::complex<double> dirichlet_kernel_f1(double x)
{
  return series_or_closed_form(Section_integral_series::get().f1, x, [x](std::complex<double> e, double x2) {
    const std::complex<double> I(0., 1.);
    const double x4 = x2 * x2;
    return (3. + I * x + x4 / 24. - I * (x4 * x) / 60. + (-3. + 2. * I * x + x2 / 2.) * e) / x4;
  });
}

/// Dirichlet kernel multiplying `<p_ij, p_ik>`; `f2(0) = -1/4`.
inline std::complex<double> dirichlet_kernel_f2(double x)
{
  return series_or_closed_form(Section_integral_series::get().f2, x, [x](std::complex<double> e, double x2) {
    const std::complex<double> I(0., 1.);
    const double x4 = x2 * x2;
    return (4. + I * x - I * (x2 * x) / 6. - x4 / 12. + I * (x4 * x) / 30. + (-4. + 3. * I * x + x2) * e) / x4;
  });
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SECTION_INTEGRALS_H
