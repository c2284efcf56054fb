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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_SEQUENTIAL_COMPONENT_SYSTEMS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_SEQUENTIAL_COMPONENT_SYSTEMS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/component_systems.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/assembly.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

// The linear systems of a field solved on this process one component at a
// time (fields on faces, and on point sets), for Component_fields
// (component_fields.h): A and M of the component being solved, and its
// factorization, both freed when it is done.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename SparseSolver>
class Sequential_component_systems
{
public:
  typedef SparseSolver Solver;
  typedef Component_factorization<SparseSolver> Factorization;
  static constexpr bool detects_indefinite = Factored_matrix<SparseSolver>::detects_indefinite;
  // the aligned systems are factored in double precision (single precision with
  // refinement is measured on vertex fields only)
  static constexpr bool aligned_in_single_precision = false;

  // `unknowns`: per component, its number of unknowns (faces, or points);
  // `user_solver`: the user's solver, copied into each factorization (or null).
  Sequential_component_systems(std::vector<std::size_t> unknowns, double length_scale, const SparseSolver* user_solver)
    : m_unknowns(std::move(unknowns)), m_length_scale(length_scale), m_user_solver(user_solver),
      m_matrices(m_unknowns.size())
  {}

  // Component c's A and M, taken from `em` (left empty), and the previous
  // component's freed (swapped with empty ones: an assignment would keep
  // their arrays).
  void set_matrices(std::size_t c, Energy_and_mass&& em)
  {
    if(m_filled) m_matrices[*m_filled] = Energy_and_mass();
    m_matrices[c] = std::move(em);
    m_filled = c;
  }

  std::size_t unknowns(std::size_t c) const { return m_unknowns[c]; }
  // eigenvalues between the normalized coordinates (lengths times length_scale) and the user's (one
  // factor at a time: the square of length_scale may underflow)
  double eigenvalue_to_user(double lambda) const { return lambda * m_length_scale * m_length_scale; }
  double eigenvalue_from_user(double lambda) const { return lambda / m_length_scale / m_length_scale; }

  const Energy_and_mass& matrices(std::size_t c) const { return m_matrices[c]; }
  Energy_and_mass* matrices_of_single_use(std::size_t) { return nullptr; }
  Complex_vector mass_times(std::size_t c, const Complex_vector& x) const { return m_matrices[c].mass * x; }
  double scale(std::size_t c) const { return eigenvalue_scale(m_matrices[c].energy, m_matrices[c].mass); }

  Factorization& factorization(std::size_t)
  {
    if(!m_factorization)
    {
      m_factorization = std::make_unique<Factorization>();
      if(m_user_solver != nullptr) m_factorization->solver = *m_user_solver;
    }
    return *m_factorization;
  }
  void release_factorization(std::size_t) { m_factorization.reset(); }
  bool user_solver() const { return m_user_solver != nullptr; }

  // These fields are solved on this process alone.
  bool certifies_definiteness(std::size_t) const { return detects_indefinite; }
  bool distributes(std::size_t) const { return false; }
  Eigen_solve_result distributed_eigenpair(std::size_t, const Eigen_solve_options&) const
  {
    throw Solver_failure_error("fields on faces and point sets have no distributed eigen-solve");
  }
  bool distributed_shifted_solve(std::size_t, double, const Complex_vector&, const Constraints&,
                                 Complex_vector&) const
  {
    return false;
  }

private:
  std::vector<std::size_t> m_unknowns;
  double m_length_scale;
  const SparseSolver* m_user_solver;
  std::vector<Energy_and_mass> m_matrices;
  std::optional<std::size_t> m_filled;  // the one component whose A and M are held
  std::unique_ptr<Factorization> m_factorization;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_SEQUENTIAL_COMPONENT_SYSTEMS_H
