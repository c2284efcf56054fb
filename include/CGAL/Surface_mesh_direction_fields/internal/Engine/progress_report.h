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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_PROGRESS_REPORT_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_PROGRESS_REPORT_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/interruption.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <optional>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

inline double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The user's progress_callback of one compute(): told the fraction done at
// each step and before each solve of the eigen-solve (through
// Eigen_solve_options::keep_going); `false` stops the computation with
// Computation_interrupted, after which the engine leaves a clean state for
// the next call (Component_systems::forget_after_failure()).
class Progress_report
{
public:
  explicit Progress_report(const std::function<bool(double)>& callback) : m_callback(callback) {}

  bool keep_going() const { return !m_callback || told(m_fraction); }

  // The step that begins at `fraction` and ends at `next` (the next step's
  // fraction, if known): within it, the eigen-solve says how far it got.
  void reached(double fraction, std::optional<double> next = std::nullopt)
  {
    m_fraction = fraction;
    m_next = next.value_or(fraction);
    if(!keep_going()) throw Computation_interrupted("the computation was interrupted (progress_callback returned false)");
  }

  // what the factorizations ask
  std::function<bool()> keep_going_test() const
  {
    if(!m_callback) return {};
    return [this] { return keep_going(); };
  }

  // what the eigen-solve asks before each solve, with the share of it done
  std::function<bool(double)> keep_going_within_step() const
  {
    if(!m_callback) return {};
    return [this](double done) { return told(m_fraction + done * (m_next - m_fraction)); };
  }

private:
  // The callback sees fractions that never decrease (an estimate within a
  // step may overshoot what a later factorization of the step reports).
  bool told(double fraction) const
  {
    m_told = (std::max)(m_told, fraction);
    return m_callback(m_told);
  }

  const std::function<bool(double)>& m_callback;
  double m_fraction = 0., m_next = 0.;
  mutable double m_told = 0.;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_PROGRESS_REPORT_H
