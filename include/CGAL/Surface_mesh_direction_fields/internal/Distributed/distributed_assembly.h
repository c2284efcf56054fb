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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_ASSEMBLY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_ASSEMBLY_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/petsc_calls.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/distributed_backend.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/local_matrices.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include <petscmat.h>

#include <algorithm>
#include <cstdint>
#include <vector>

// The matrices A and M of one component, spread over the processes of an
// MPI communicator by rows (user manual, section "Several Processes"). The
// mesh is on the first process (rank 0), which computes the tangent spaces
// and the connection (a few numbers per corner); the local matrices, the
// assembly and everything after are split. A component's vertices are
// numbered in the breadth-first order of components.h and cut into equal
// ranges, one per process: the border between two ranges is a front of the
// search, so few edges cross it. A face goes to the process of its
// lowest-numbered vertex, which receives it as a self-contained record (its
// points, area, holonomy and transports) and computes its local matrices with
// the same function as the single-process path, so every entry is the same
// number; PETSc sends the entries of rows owned elsewhere at assembly.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// What one face contributes, independently of the rest of the mesh.
struct Face_record
{
  std::int64_t row[3];  // the component's numbering of faces[f][c]
  double point[3][3];
  double area;
  double holonomy;
  Complex transport[3];
};

// The first row of each process's range (and the number of rows at the end).
inline std::vector<std::int64_t> row_ranges(std::int64_t rows, int processes)
{
  std::vector<std::int64_t> first(static_cast<std::size_t>(processes) + 1);
  for(int p = 0; p <= processes; ++p) first[static_cast<std::size_t>(p)] = rows * p / processes;
  return first;
}

inline int owner_of_row(const std::vector<std::int64_t>& first, std::int64_t row)
{
  return static_cast<int>(std::upper_bound(first.begin(), first.end(), row) - first.begin()) - 1;
}

// For each row, the distinct columns of its entries in its own process's
// range (the diagonal included) and in other ranges: PETSc's exact
// preallocation.
inline void count_row_entries(const Assembly_source& source, const std::vector<std::int64_t>& first,
                              std::vector<PetscInt>& in_range, std::vector<PetscInt>& out_of_range)
{
  const Indexed_mesh& m = *source.mesh;
  const Component& comp = *source.component;
  in_range.assign(comp.vertices.size(), 1);
  out_of_range.assign(comp.vertices.size(), 0);
  std::vector<std::int64_t> neighbours;
  for(std::size_t row = 0; row < comp.vertices.size(); ++row)
  {
    neighbours.clear();
    for(std::size_t corner : m.fan(comp.vertices[row]))
      for(std::size_t other : {Indexed_mesh::next_corner(corner), Indexed_mesh::previous_corner(corner)})
        neighbours.push_back(static_cast<std::int64_t>((*source.local_index)[m.vertex_of_corner(other)]));
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    const int owner = owner_of_row(first, static_cast<std::int64_t>(row));
    for(std::int64_t column : neighbours)
      ++(owner_of_row(first, column) == owner ? in_range : out_of_range)[row];
  }
}

inline Face_record face_record(const Assembly_source& source, std::size_t f)
{
  const Indexed_mesh& m = *source.mesh;
  Face_record record;
  for(int c = 0; c < 3; ++c)
  {
    const std::size_t v = m.faces[f][c];
    record.row[c] = static_cast<std::int64_t>((*source.local_index)[v]);
    std::copy(m.points[v].begin(), m.points[v].end(), record.point[c]);
    record.transport[c] = source.connection->transport[3 * f + c];
  }
  record.area = source.tangent_spaces->face_area[f];
  record.holonomy = source.connection->holonomy[f];
  return record;
}

// Adds the local matrices of `records` into A and M, computed by
// local_matrices() on a small mesh made of these faces alone (which is all
// it reads: the points, the area, the holonomy and the transports of a face).
inline void add_local_matrices(const std::vector<Face_record>& records, double mollification, double s, Mat A, Mat M)
{
  Indexed_mesh m;
  Tangent_spaces ts;
  Connection con;
  ts.mollification = mollification;
  for(const Face_record& record : records)
  {
    const std::size_t base = m.points.size();
    for(int c = 0; c < 3; ++c)
    {
      m.points.push_back({record.point[c][0], record.point[c][1], record.point[c][2]});
      con.transport.push_back(record.transport[c]);
    }
    m.faces.push_back({base, base + 1, base + 2});
    ts.face_area.push_back(record.area);
    con.holonomy.push_back(record.holonomy);
  }
  for(std::size_t f = 0; f < records.size(); ++f)
  {
    const Local_matrices lm = local_matrices(m, ts, con, f, s);
    PetscInt rows[3];
    PetscScalar energy[9], mass[9];
    for(int c = 0; c < 3; ++c)
    {
      rows[c] = static_cast<PetscInt>(records[f].row[c]);
      energy[4 * c] = lm.energy_diagonal[c];
      mass[4 * c] = lm.mass_diagonal[c];
      // pair c: (row k, column j) with j = c+1, k = c+2, and its conjugate at (j, k)
      const int j = (c + 1) % 3, k = (c + 2) % 3;
      energy[3 * k + j] = lm.energy_pair[c];
      mass[3 * k + j] = lm.mass_pair[c];
      energy[3 * j + k] = std::conj(lm.energy_pair[c]);
      mass[3 * j + k] = std::conj(lm.mass_pair[c]);
    }
    CGAL_SMDF_PETSC_CALL(MatSetValues(A, 3, rows, 3, rows, energy, ADD_VALUES));
    CGAL_SMDF_PETSC_CALL(MatSetValues(M, 3, rows, 3, rows, mass, ADD_VALUES));
  }
}

// Faces travel in pieces of this many, so that no buffer holds a large part
// of the mesh.
constexpr std::size_t face_records_per_message = std::size_t(1) << 16;

// Rank 0: each process's faces, sent in pieces (an empty piece ends), then
// its own added.
inline void send_faces(MPI_Comm comm, const Assembly_source& source, const std::vector<std::int64_t>& first,
                       double s, Mat A, Mat M)
{
  int processes;
  CGAL_SMDF_MPI_CALL(MPI_Comm_size(comm, &processes));
  const Component& comp = *source.component;
  std::vector<std::vector<Compact_index> > faces_of(static_cast<std::size_t>(processes));
  for(std::size_t f : comp.faces)
  {
    std::int64_t lowest = INT64_MAX;
    for(int c = 0; c < 3; ++c)
      lowest = (std::min)(lowest, static_cast<std::int64_t>((*source.local_index)[source.mesh->faces[f][c]]));
    faces_of[static_cast<std::size_t>(owner_of_row(first, lowest))].push_back(f);
  }
  std::vector<Face_record> records;
  for(int p = processes - 1; p >= 0; --p)  // rank 0's own faces last: the others start computing sooner
  {
    const std::vector<Compact_index>& faces = faces_of[static_cast<std::size_t>(p)];
    for(std::size_t begin = 0;; begin += face_records_per_message)
    {
      const std::size_t end = (std::min)(faces.size(), begin + face_records_per_message);
      records.clear();
      for(std::size_t k = begin; k < end; ++k) records.push_back(face_record(source, faces[k]));
      if(p == 0)
        add_local_matrices(records, source.tangent_spaces->mollification, s, A, M);
      else
        CGAL_SMDF_MPI_CALL(MPI_Send(records.data(), static_cast<int>(records.size() * sizeof(Face_record)), MPI_BYTE, p, 0, comm));
      if(end == faces.size() && (p == 0 || records.empty())) break;
    }
  }
}

// Any other rank: the pieces from rank 0, until an empty one, all received
// before any is computed. Rank 0's sends of large pieces complete only when
// this process is inside MPI, so computing each piece as it arrives would
// make rank 0 wait for that computation before it could go on with its own.
inline void receive_faces(MPI_Comm comm, double mollification, double s, Mat A, Mat M)
{
  std::vector<std::vector<Face_record> > pieces;
  for(;;)
  {
    MPI_Status status;
    CGAL_SMDF_MPI_CALL(MPI_Probe(0, 0, comm, &status));
    int bytes = 0;
    CGAL_SMDF_MPI_CALL(MPI_Get_count(&status, MPI_BYTE, &bytes));
    pieces.emplace_back(static_cast<std::size_t>(bytes) / sizeof(Face_record));
    CGAL_SMDF_MPI_CALL(MPI_Recv(pieces.back().data(), bytes, MPI_BYTE, 0, 0, comm, MPI_STATUS_IGNORE));
    if(pieces.back().empty()) break;
  }
  for(std::vector<Face_record>& piece : pieces)
  {
    add_local_matrices(piece, mollification, s, A, M);
    std::vector<Face_record>().swap(piece);
  }
}

struct Distributed_matrices
{
  Mat energy = nullptr, mass = nullptr;
  std::int64_t rows = 0;
  std::size_t cut_edges = 0;  // edges between vertices of different processes (on rank 0)
  void destroy()
  {
    if(energy) CGAL_SMDF_PETSC_CALL(MatDestroy(&energy));
    if(mass) CGAL_SMDF_PETSC_CALL(MatDestroy(&mass));
  }
};

// Collective: A and M of the component of `source` (given on rank 0 only)
// for the energy E_s, each process holding the rows of its range.
inline Distributed_matrices assemble_distributed(MPI_Comm comm, const Assembly_source& source, double s)
{
  int rank, processes;
  CGAL_SMDF_MPI_CALL(MPI_Comm_rank(comm, &rank));
  CGAL_SMDF_MPI_CALL(MPI_Comm_size(comm, &processes));
  Distributed_matrices result;
  double mollification = 0.;
  if(rank == 0)
  {
    result.rows = static_cast<std::int64_t>(source.component->vertices.size());
    mollification = source.tangent_spaces->mollification;
  }
  CGAL_SMDF_MPI_CALL(MPI_Bcast(&result.rows, 1, MPI_INT64_T, 0, comm));
  CGAL_SMDF_MPI_CALL(MPI_Bcast(&mollification, 1, MPI_DOUBLE, 0, comm));
  const std::vector<std::int64_t> first = row_ranges(result.rows, processes);
  const int local_rows = static_cast<int>(first[static_cast<std::size_t>(rank) + 1] - first[static_cast<std::size_t>(rank)]);

  std::vector<PetscInt> in_range, out_of_range;
  std::vector<int> counts(static_cast<std::size_t>(processes)), offsets(static_cast<std::size_t>(processes));
  if(rank == 0)
  {
    count_row_entries(source, first, in_range, out_of_range);
    for(std::size_t row = 0; row < in_range.size(); ++row) result.cut_edges += static_cast<std::size_t>(out_of_range[row]);
    result.cut_edges /= 2;
    for(int p = 0; p < processes; ++p)
    {
      counts[static_cast<std::size_t>(p)] = static_cast<int>(first[static_cast<std::size_t>(p) + 1] - first[static_cast<std::size_t>(p)]);
      offsets[static_cast<std::size_t>(p)] = static_cast<int>(first[static_cast<std::size_t>(p)]);
    }
  }
  std::vector<PetscInt> my_in(static_cast<std::size_t>(local_rows)), my_out(static_cast<std::size_t>(local_rows));
  CGAL_SMDF_MPI_CALL(MPI_Scatterv(in_range.data(), counts.data(), offsets.data(), MPIU_INT, my_in.data(), local_rows, MPIU_INT, 0, comm));
  CGAL_SMDF_MPI_CALL(MPI_Scatterv(out_of_range.data(), counts.data(), offsets.data(), MPIU_INT, my_out.data(), local_rows, MPIU_INT, 0, comm));
  std::vector<PetscInt>().swap(in_range);
  std::vector<PetscInt>().swap(out_of_range);

  const PetscInt n = static_cast<PetscInt>(result.rows);
  for(Mat* S : {&result.energy, &result.mass})
    CGAL_SMDF_PETSC_CALL(MatCreateAIJ(comm, local_rows, local_rows, n, n, 0, my_in.data(), 0, my_out.data(), S));
  if(rank == 0)
    send_faces(comm, source, first, s, result.energy, result.mass);
  else
    receive_faces(comm, mollification, s, result.energy, result.mass);
  for(Mat S : {result.energy, result.mass})
  {
    CGAL_SMDF_PETSC_CALL(MatAssemblyBegin(S, MAT_FINAL_ASSEMBLY));
    CGAL_SMDF_PETSC_CALL(MatAssemblyEnd(S, MAT_FINAL_ASSEMBLY));
    CGAL_SMDF_PETSC_CALL(MatSetOption(S, MAT_HERMITIAN, PETSC_TRUE));
  }
  return result;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_ASSEMBLY_H
