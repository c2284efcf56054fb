// f1, f2 and the mass factor against a 150-digit reference evaluation of their
// closed forms (user manual, section "Energies"), on a dense sample of [-6 pi, 6 pi] that
// includes |Omega| < 1e-6 and Omega = 0.

#include <CGAL/Surface_mesh_direction_fields/internal/Method/section_integrals.h>

#include "test_support.h"

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <complex>
#include <iostream>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields::internal;
typedef boost::multiprecision::number<boost::multiprecision::cpp_bin_float<150> > Real;

struct Complex_real { Real re, im; };

// e^{ix} * (a + ib) + (c + id), all in high precision
static Complex_real reference(int which, double xd)
{
  const Real x = xd;
  const Real c = cos(x), s = sin(x);
  const Real x2 = x * x, x3 = x2 * x, x4 = x2 * x2, x5 = x4 * x;
  Real pre, pim, qre, qim;  // numerator = (pre + i pim) + (qre + i qim) e^{ix}
  if(which == 0) {        // mass: (6 e^{ix} - 6 - 6ix + 3x^2 + ix^3) / (3 x^4)
    pre = -6 + 3 * x2; pim = -6 * x + x3; qre = 6; qim = 0;
  } else if(which == 1) { // f1
    pre = 3 + x4 / 24; pim = x - x5 / 60; qre = -3 + x2 / 2; qim = 2 * x;
  } else {                // f2
    pre = 4 - x4 / 12; pim = x - x3 / 6 + x5 / 30; qre = -4 + x2; qim = 3 * x;
  }
  Real nre = pre + qre * c - qim * s;
  Real nim = pim + qre * s + qim * c;
  Real den = (which == 0) ? 3 * x4 : x4;
  return Complex_real{nre / den, nim / den};
}

static std::complex<double> value_at_zero(int which)
{
  if(which == 0) return {1. / 12., 0.};
  if(which == 1) return {0., 0.};
  return {-0.25, 0.};
}

int main()
{
  Test_report report("section integrals");
  std::vector<double> xs;
  const double pi = 3.14159265358979323846;
  for(int i = -6000; i <= 6000; ++i)
    xs.push_back(6. * pi * i / 6000.);
  for(double a = 1e-12; a < 3.; a *= 1.1) { xs.push_back(a); xs.push_back(-a); }
  for(double a : {1e-300, 1e-30, 1e-15, 1e-9, 5e-7, 1e-6, 1.999999999, 2., 2.000000001})
  { xs.push_back(a); xs.push_back(-a); }

  const char* names[3] = {"mass_factor", "f1", "f2"};
  for(int which = 0; which < 3; ++which)
  {
    double worst = 0., worst_x = 0.;
    for(double x : xs)
    {
      std::complex<double> got = which == 0 ? SMDF::mass_factor(x)
                               : which == 1 ? SMDF::dirichlet_kernel_f1(x)
                                            : SMDF::dirichlet_kernel_f2(x);
      double err;
      if(std::abs(x) < 1e-25) {
        // below 1e-25 the 150-digit closed form itself cancels: compare to the limit
        std::complex<double> ref = value_at_zero(which);
        double scale = (which == 1) ? std::abs(x) / 24. : std::abs(ref);
        err = (scale == 0.) ? std::abs(got) : std::abs(got - ref) / scale;
        if(which == 1 && x != 0.) err = std::abs(got - std::complex<double>(0., -x / 24.)) / scale;
      } else {
        Complex_real ref = reference(which, x);
        Real dre = Real(got.real()) - ref.re, dim = Real(got.imag()) - ref.im;
        Real num = sqrt(dre * dre + dim * dim), den = sqrt(ref.re * ref.re + ref.im * ref.im);
        err = static_cast<double>(num / den);
      }
      if(err > worst) { worst = err; worst_x = x; }
    }
    std::cout << names[which] << ": worst relative error " << worst << " at x = " << worst_x << "\n";
    report.check(worst <= 1e-14, std::string(names[which]) + " relative error <= 1e-14");
  }
  // exact values at 0 and the symmetry f(-x) = conj(f(x))
  report.check(SMDF::mass_factor(0.) == std::complex<double>(1. / 12., 0.), "mass_factor(0) = 1/12");
  report.check(SMDF::dirichlet_kernel_f1(0.) == std::complex<double>(0., 0.), "f1(0) = 0");
  report.check(SMDF::dirichlet_kernel_f2(0.) == std::complex<double>(-0.25, 0.), "f2(0) = -1/4");
  for(double x : {0.3, 1.7, 2.5, 9.})
    report.check(SMDF::dirichlet_kernel_f2(-x) == std::conj(SMDF::dirichlet_kernel_f2(x)), "f2(-x) = conj f2(x)");
  return report.finish();
}
