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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_ASSEMBLY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_ASSEMBLY_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/huge_pages.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/prefetch.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/local_matrices.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <new>
#include <type_traits>
#include <optional>
#include <utility>
#include <vector>

// The global energy and mass matrices A and M of each component, gathered
// from the local matrices of its faces (local_matrices.h; user manual,
// section "Energies"). Both triangles are stored, in compressed columns.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Energy_and_mass
{
  Complex_sparse_matrix energy;  // A, Hermitian positive semi-definite
  Complex_sparse_matrix mass;    // M, Hermitian positive definite

  // Eigen 3.4's sparse matrices have no move constructor or assignment: a
  // returned pair stored in place (matrices[c] = assemble_component(...))
  // would copy both arrays, and touch a second A and M. Moves swap them.
  Energy_and_mass() = default;
  Energy_and_mass(const Energy_and_mass&) = default;
  Energy_and_mass& operator=(const Energy_and_mass&) = default;
  Energy_and_mass(Energy_and_mass&& other) noexcept { *this = std::move(other); }
  Energy_and_mass& operator=(Energy_and_mass&& other) noexcept
  {
    energy.swap(other.energy);
    mass.swap(other.mass);
    return *this;
  }
};

// The local matrices of all faces, in storage that is constructed in place
// by the loop computing them: a std::vector would first clear it, in one
// sequential pass (std::complex zero-initializes), a large part of this
// step's time on large meshes. Only the faces given to construct() may be
// read.
class Local_matrix_array
{
  static_assert(std::is_trivially_destructible<Local_matrices>::value, "no destructor is called");
  std::allocator<Local_matrices> m_allocator;
  Local_matrices* m_data;
  std::size_t m_size;

public:
  explicit Local_matrix_array(std::size_t n) : m_data(m_allocator.allocate(n)), m_size(n)
  {
    advise_huge_pages(m_data, n * sizeof(Local_matrices));
  }
  ~Local_matrix_array() { m_allocator.deallocate(m_data, m_size); }
  Local_matrix_array(const Local_matrix_array&) = delete;
  Local_matrix_array& operator=(const Local_matrix_array&) = delete;

  void construct(std::size_t f, const Local_matrices& lm) { new(m_data + f) Local_matrices(lm); }
  const Local_matrices& operator[](std::size_t f) const { return m_data[f]; }
  void prefetch(std::size_t f) const { prefetch_range(m_data + f, sizeof(Local_matrices)); }
};

// The local matrices of every face (indexed by face); the faces are
// independent, so this runs in parallel when TBB is available.
inline void compute_all_local_matrices(const Indexed_mesh& m, const Tangent_spaces& ts, const Connection& con,
                                       double s, Local_matrix_array& local)
{
  parallel_for_each_face(m, [&](std::size_t f) { local.construct(f, local_matrices(m, ts, con, f, s)); });
}

struct Column_entry
{
  Eigen::Index row;
  Complex energy, mass;
};

// The entries of column v (global vertex index) of A and M, sorted by row, by
// gathering from the faces of v's fan; gathering (rather than scattering
// face by face) lets columns be filled in parallel without conflicts.
// In face t with v = t[c]: v is the vertex j of pair (c+2)%3, whose k is
// t[c+1], so (row t[c+1], column v) holds that pair's value; and v is the
// vertex k of pair (c+1)%3, whose j is t[c+2], so (row t[c+2], column v)
// holds the conjugate of that pair's value (see Local_matrices).
// The fan is counter-clockwise, so the vertex t[c+2] of one corner is the
// vertex t[c+1] of the next (and, in a closed fan, the last corner's is the
// first corner's): their two contributions are added as they come, which
// leaves one entry per neighbour to sort instead of two. Rows that still
// repeat (a multiple edge) are merged after the sort.
inline void gather_column(const Indexed_mesh& m, const Local_matrix_array& local,
                          const std::vector<Compact_index>& local_index, std::size_t v,
                          std::vector<Column_entry>& column)
{
  column.clear();
  double energy_diagonal = 0., mass_diagonal = 0.;
  for(std::size_t k = m.fan_offsets[v]; k < m.fan_offsets[v + 1]; ++k)
  {
    const std::size_t corner = m.fan_corners[k], f = corner / 3;
    const int c = static_cast<int>(corner % 3), after = (c + 1) % 3, before = (c + 2) % 3;
    const Local_matrices& lm = local[f];
    energy_diagonal += lm.energy_diagonal[c];
    mass_diagonal += lm.mass_diagonal[c];
    const auto row_after = static_cast<Eigen::Index>(local_index[m.faces[f][after]]);
    if(!column.empty() && column.back().row == row_after)
    {
      column.back().energy += lm.energy_pair[before];
      column.back().mass += lm.mass_pair[before];
    }
    else
      column.push_back({row_after, lm.energy_pair[before], lm.mass_pair[before]});
    column.push_back({static_cast<Eigen::Index>(local_index[m.faces[f][before]]), std::conj(lm.energy_pair[after]),
                      std::conj(lm.mass_pair[after])});
  }
  if(column.size() > 2 && column.back().row == column.front().row)  // a closed fan
  {
    column.front().energy += column.back().energy;
    column.front().mass += column.back().mass;
    column.pop_back();
  }
  column.push_back({static_cast<Eigen::Index>(local_index[v]), Complex(energy_diagonal, 0.),
                    Complex(mass_diagonal, 0.)});
  // sorted by row, stably (equal rows then add up in fan order): insertion
  // sort for the usual column of about 7 entries, a merge sort for a vertex
  // of high valence (insertion sort is quadratic in the valence)
  if(column.size() <= 32)
  {
    for(std::size_t a = 1; a < column.size(); ++a)
      for(std::size_t b = a; b > 0 && column[b].row < column[b - 1].row; --b)
        std::swap(column[b], column[b - 1]);
  }
  else
    std::stable_sort(column.begin(), column.end(),
                     [](const Column_entry& x, const Column_entry& y) { return x.row < y.row; });
  std::size_t last = 0;
  for(std::size_t a = 1; a < column.size(); ++a)
  {
    if(column[a].row == column[last].row)
    {
      column[last].energy += column[a].energy;
      column[last].mass += column[a].mass;
    }
    else
      column[++last] = column[a];
  }
  column.resize(last + 1);
}

// Writes the columns of A and M, whose sizes are given, directly into the
// compressed arrays (in parallel: each column gathers its own entries).
// Returns false if a column's size is not the given one.
inline bool fill_columns(const Indexed_mesh& m, const Local_matrix_array& local, const Component& comp,
                         const std::vector<Compact_index>& local_index,
                         const std::vector<Complex_sparse_matrix::StorageIndex>& column_size, Energy_and_mass& em)
{
  typedef Complex_sparse_matrix::StorageIndex Storage_index;
  const std::size_t nc = comp.vertices.size();
  const auto n = static_cast<Eigen::Index>(nc);
  em.energy.resize(n, n);
  em.mass.resize(n, n);
  std::size_t nnz = 0;
  for(Storage_index size : column_size) nnz += static_cast<std::size_t>(size);
  em.energy.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  em.mass.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  Storage_index* outer_a = em.energy.outerIndexPtr();
  Storage_index* outer_m = em.mass.outerIndexPtr();
  outer_a[0] = outer_m[0] = 0;
  for(std::size_t jl = 0; jl < nc; ++jl)
    outer_a[jl + 1] = outer_m[jl + 1] = outer_a[jl] + column_size[jl];

  Storage_index* inner_a = em.energy.innerIndexPtr();
  Storage_index* inner_m = em.mass.innerIndexPtr();
  Complex* value_a = em.energy.valuePtr();
  Complex* value_m = em.mass.valuePtr();
  std::vector<unsigned char> size_ok(nc, 1);
  parallel_for_each_range(nc, [&](std::size_t begin, std::size_t end) {
    std::vector<Column_entry> column;
    for(std::size_t jl = begin; jl < end; ++jl)
    {
      // the local matrices of the faces of a column two steps ahead (see prefetch.h)
      if(jl + 2 < end)
      {
        const std::size_t ahead = comp.vertices[jl + 2];
        for(std::size_t k = m.fan_offsets[ahead]; k < m.fan_offsets[ahead + 1]; ++k)
          local.prefetch(m.fan_corners[k] / 3);
      }
      gather_column(m, local, local_index, comp.vertices[jl], column);
      if(column.size() != static_cast<std::size_t>(column_size[jl]))
      {
        size_ok[jl] = 0;
        continue;
      }
      Storage_index p = outer_a[jl];
      for(const Column_entry& e : column)
      {
        inner_a[p] = inner_m[p] = static_cast<Storage_index>(e.row);
        value_a[p] = e.energy;
        value_m[p] = e.mass;
        ++p;
      }
    }
  });
  return std::find(size_ok.begin(), size_ok.end(), 0) == size_ok.end();
}

// Assembles A and M (both triangles stored, compressed column storage) of one
// component from the local matrices of all faces: the pattern and the values
// are written directly into the compressed arrays, without triplets, in one
// gathering pass when the fans have no multiple edge (two otherwise).
inline Energy_and_mass assemble_component(const Indexed_mesh& m, const Local_matrix_array& local,
                                          const Component& comp, const std::vector<Compact_index>& local_index)
{
  typedef Complex_sparse_matrix::StorageIndex Storage_index;
  const std::size_t nc = comp.vertices.size();
  // The size of each column: on a manifold fan, v and one neighbour per
  // corner, plus one more at a boundary vertex. A fan can repeat a neighbour
  // only through a multiple edge; the fill below detects it and the sizes are
  // then counted by a gathering pass.
  std::vector<Storage_index> column_size(nc);
  for(std::size_t jl = 0; jl < nc; ++jl)
  {
    const std::size_t v = comp.vertices[jl];
    column_size[jl] = static_cast<Storage_index>(1 + m.fan_size(v) + (m.is_border_vertex[v] ? 1 : 0));
  }
  Energy_and_mass em;
  if(fill_columns(m, local, comp, local_index, column_size, em))
    return em;
  parallel_for_each_range(nc, [&](std::size_t begin, std::size_t end) {
    std::vector<Column_entry> column;
    for(std::size_t jl = begin; jl < end; ++jl)
    {
      gather_column(m, local, local_index, comp.vertices[jl], column);
      column_size[jl] = static_cast<Storage_index>(column.size());
    }
  });

  const bool filled = fill_columns(m, local, comp, local_index, column_size, em);
  CGAL_assertion(filled);
  CGAL_USE(filled);
  return em;
}

// The lower triangle (diagonal included) of A + shift M of one component,
// without A and M, and trace(A) / trace(M): what a single solve with A +
// shift M needs (the aligned field of a single call; see
// Globally_optimal_direction_field::factor_aligned_system()). The values are
// those of shifted_lower_triangle(A, M, shift), bit for bit.
struct Shifted_lower_triangle
{
  Complex_sparse_matrix matrix;
  double shift = 0.;
  double eigenvalue_scale = 0.;  // trace(A) / trace(M)

  Shifted_lower_triangle() = default;
  Shifted_lower_triangle(const Shifted_lower_triangle&) = default;
  Shifted_lower_triangle& operator=(const Shifted_lower_triangle&) = default;
  Shifted_lower_triangle(Shifted_lower_triangle&& other) noexcept { *this = std::move(other); }
  Shifted_lower_triangle& operator=(Shifted_lower_triangle&& other) noexcept  // a swap, as Energy_and_mass's
  {
    matrix.swap(other.matrix);
    shift = other.shift;
    eigenvalue_scale = other.eigenvalue_scale;
    return *this;
  }
};

// The number of rows jl or below in local column jl, assuming that the fan of
// its vertex v repeats no neighbour: v itself and its neighbours below it.
inline Complex_sparse_matrix::StorageIndex lower_column_size(const Indexed_mesh& m,
                                                             const std::vector<Compact_index>& local_index,
                                                             std::size_t v, std::size_t jl)
{
  Complex_sparse_matrix::StorageIndex size = 1;
  m.for_each_neighbour(v, [&](std::size_t w) { size += static_cast<std::size_t>(local_index[w]) > jl ? 1 : 0; });
  return size;
}

inline Shifted_lower_triangle assemble_shifted_lower_triangle(const Indexed_mesh& m, const Local_matrix_array& local,
                                                              const Component& comp,
                                                              const std::vector<Compact_index>& local_index,
                                                              double shift)
{
  typedef Complex_sparse_matrix::StorageIndex Storage_index;
  const std::size_t nc = comp.vertices.size();
  std::vector<Storage_index> column_size(nc);
  parallel_for_each_index(nc, [&](std::size_t jl) {
    column_size[jl] = lower_column_size(m, local_index, comp.vertices[jl], jl);
  });
  std::vector<double> energy_diagonal(nc), mass_diagonal(nc);
  Shifted_lower_triangle result;
  result.shift = shift;
  Complex_sparse_matrix& S = result.matrix;
  S.resize(static_cast<Eigen::Index>(nc), static_cast<Eigen::Index>(nc));
  // Fills the columns whose size is right; returns false if one is not (a
  // multiple edge), with the true sizes in column_size.
  auto fill = [&]() {
    Storage_index* outer = S.outerIndexPtr();
    outer[0] = 0;
    for(std::size_t jl = 0; jl < nc; ++jl) outer[jl + 1] = outer[jl] + column_size[jl];
    S.resizeNonZeros(outer[nc]);
    Storage_index* inner = S.innerIndexPtr();
    Complex* value = S.valuePtr();
    std::vector<unsigned char> size_ok(nc, 1);
    parallel_for_each_range(nc, [&](std::size_t begin, std::size_t end) {
      std::vector<Column_entry> column;
      for(std::size_t jl = begin; jl < end; ++jl)
      {
        gather_column(m, local, local_index, comp.vertices[jl], column);
        const auto first = std::lower_bound(column.begin(), column.end(), static_cast<Eigen::Index>(jl),
                                            [](const Column_entry& e, Eigen::Index row) { return e.row < row; });
        energy_diagonal[jl] = first->energy.real();
        mass_diagonal[jl] = first->mass.real();
        if(column.end() - first != column_size[jl])
        {
          size_ok[jl] = 0;
          column_size[jl] = static_cast<Storage_index>(column.end() - first);
          continue;
        }
        Storage_index p = outer[jl];
        for(auto e = first; e != column.end(); ++e, ++p)
        {
          inner[p] = static_cast<Storage_index>(e->row);
          value[p] = e->energy + shift * e->mass;
        }
      }
    });
    return std::find(size_ok.begin(), size_ok.end(), 0) == size_ok.end();
  };
  if(!fill())
  {
    const bool filled = fill();
    CGAL_assertion(filled);
    CGAL_USE(filled);
  }
  double energy_trace = 0., mass_trace = 0.;
  for(std::size_t jl = 0; jl < nc; ++jl)
  {
    energy_trace += energy_diagonal[jl];
    mass_trace += mass_diagonal[jl];
  }
  result.eigenvalue_scale = energy_trace / mass_trace;
  return result;
}

// A and M of every component; except, for the components with a number in
// `shift_only` (none for the others, or empty), only the lower triangle of
// A + shift M, into `shifted` (their A and M are left empty).
inline std::vector<Energy_and_mass> assemble_energy_and_mass(const Indexed_mesh& m, const Tangent_spaces& ts,
                                                             const Connection& con, const Components& comps,
                                                             double s,
                                                             const std::vector<std::optional<double> >& shift_only = {},
                                                             std::vector<Shifted_lower_triangle>* shifted = nullptr)
{
  Local_matrix_array local(ts.face_area.size());
  compute_all_local_matrices(m, ts, con, s, local);
  std::vector<Energy_and_mass> matrices(comps.list.size());
  if(shifted != nullptr) shifted->assign(comps.list.size(), Shifted_lower_triangle());
  for(std::size_t c = 0; c < comps.list.size(); ++c)
  {
    if(shifted != nullptr && c < shift_only.size() && shift_only[c])
      (*shifted)[c] = assemble_shifted_lower_triangle(m, local, comps.list[c], comps.local_index, *shift_only[c]);
    else
      matrices[c] = assemble_component(m, local, comps.list[c], comps.local_index);
  }
  return matrices;
}

// A and M of one component (computes the local matrices of its faces only).
inline Energy_and_mass assemble_energy_and_mass(const Indexed_mesh& m, const Tangent_spaces& ts,
                                                const Connection& con, const Component& comp,
                                                const std::vector<Compact_index>& local_index, double s)
{
  Local_matrix_array local(m.number_of_faces());
  for(std::size_t f : comp.faces) local.construct(f, local_matrices(m, ts, con, f, s));
  return assemble_component(m, local, comp, local_index);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_ASSEMBLY_H
