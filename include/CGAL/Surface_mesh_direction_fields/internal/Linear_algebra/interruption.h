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

// Stopping a long factorization on request. A computation installs a check
// (false: stop) on its thread for its duration (Scoped_interruption_check);
// the supernodal factorization, which takes the longest time without any
// other point where a progress callback is asked, polls it
// (Interruption_poll) between supernodes on that thread only, at most once
// every few milliseconds, so that an interrupt (Ctrl-C in Python) is seen
// within a fraction of a second without a cost on the factorization. The
// share of an iteration done (share_done()) is what a progress callback is
// told inside the eigen-solve.
#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_INTERRUPTION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_INTERRUPTION_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// the check installed on this thread (null: none)
inline const std::function<bool()>*& installed_interruption_check()
{
  thread_local const std::function<bool()>* check = nullptr;
  return check;
}

class Scoped_interruption_check
{
  std::function<bool()> m_check;
  const std::function<bool()>* m_previous;

public:
  explicit Scoped_interruption_check(std::function<bool()> check)
    : m_check(std::move(check)), m_previous(installed_interruption_check())
  {
    if(m_check) installed_interruption_check() = &m_check;
  }
  ~Scoped_interruption_check() { installed_interruption_check() = m_previous; }
  Scoped_interruption_check(const Scoped_interruption_check&) = delete;
  Scoped_interruption_check& operator=(const Scoped_interruption_check&) = delete;
};

// Made by a long loop on the thread that runs it; stopped() may be called
// from any of the loop's threads and asks the check only on the first one.
class Interruption_poll
{
  typedef std::chrono::steady_clock Clock;
  const std::function<bool()>* m_check = installed_interruption_check();
  std::thread::id m_caller = std::this_thread::get_id();
  Clock::time_point m_next = Clock::now() + interval();
  std::atomic<bool> m_stopped{false};

  static Clock::duration interval() { return std::chrono::milliseconds(20); }

public:
  bool stopped()
  {
    if(m_check != nullptr && std::this_thread::get_id() == m_caller && Clock::now() >= m_next)
    {
      if(!(*m_check)()) m_stopped.store(true);
      m_next = Clock::now() + interval();
    }
    return m_stopped.load(std::memory_order_relaxed);
  }

  // once the loop's threads have joined
  void throw_if_stopped() const
  {
    if(m_stopped.load()) throw Computation_interrupted("the computation was interrupted during a factorization");
  }
};

// The share of an iteration done, for a progress report: the solves made
// against those made plus those still needed at the last solve's rate of
// fall of the residual (`residuals`: after each solve, the start's first)
// toward `tolerance`.
inline double share_done(const std::vector<double>& residuals, double tolerance)
{
  const std::size_t solves = residuals.size() - 1;
  if(solves == 0) return 0.;
  const double rate = std::log(residuals[solves - 1] / residuals[solves]);
  const double left = std::log(residuals[solves] / tolerance);
  if(!(rate > 0.) || !std::isfinite(rate) || !std::isfinite(left)) return 0.;
  const double share = static_cast<double>(solves) / (static_cast<double>(solves) + (std::max)(0., left / rate));
  return (std::min)(0.99, share);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_INTERRUPTION_H
