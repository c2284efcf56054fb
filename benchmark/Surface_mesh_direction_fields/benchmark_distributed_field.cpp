// The smoothest field (n = 4) of a mesh's largest component over the
// processes of mpirun, on the distributed path (issue: "Beyond one
// machine"): the mesh only on rank 0, the rows of A and M assembled by each
// process from its faces (internal/Distributed/distributed_assembly.h), the
// eigenpair by LOBPCG with GAMG in the gauge of a local estimate
// (internal/Distributed/distributed_eigen_solve.h), the eigenvector
// gathered on rank 0. Prints the time of each step, the peak resident memory
// of every process, the edge cut and the singular faces.
//
//   mpirun -np K build/bin/benchmark_distributed_field MESH [--single] [--compare] [--slepc-lobpcg]
//                                                      [--partition-cut] [PETSc options]
//
// --single runs the package's single-process eigen-solve instead (the
// reference for time and memory, one process); --compare runs it as well,
// after the distributed one, on rank 0, and prints the relative difference
// of the eigenvalues and the singular faces found by only one of them.
// --slepc-lobpcg uses SLEPc's LOBPCG instead of the package's.
// --partition-cut also prints the edge cut of PT-Scotch's partition of the
// component's vertex graph into K parts (PETSc's MatPartitioning), against
// that of the breadth-first ranges the package uses.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/distributed_eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/distributed_assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/singularities.h>

#include "largest_component.h"
#include "process_memory.h"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SI = CGAL::Surface_mesh_direction_fields::internal;
typedef CGAL::Surface_mesh_direction_fields::Default_direction_field_solver Solver;
typedef std::chrono::steady_clock Clock;

namespace {

double ms_since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The mesh data of rank 0: the largest component with its tangent spaces and
// connection for n = 4.
struct Mesh_data : Largest_component<Mesh>
{
  explicit Mesh_data(const Mesh& mesh) : Largest_component<Mesh>(mesh) {}

  // The faces of nonzero index of the field given on the component's vertices.
  std::vector<std::size_t> singular_faces(const SI::Complex_vector& x) const
  {
    std::vector<std::complex<double> > u(m.number_of_vertices(), std::complex<double>(0., 0.));
    for(std::size_t i = 0; i < component().vertices.size(); ++i) u[component().vertices[i]] = x[static_cast<Eigen::Index>(i)];
    const std::vector<int> index = SI::face_indices(m, con, u);
    std::vector<std::size_t> singular;
    for(std::size_t f : component().faces)
      if(index[f] != 0) singular.push_back(f);
    return singular;
  }
};

struct Single_result
{
  double eigenvalue = 0., ms = 0.;
  SI::Complex_vector vector;
};

Single_result single_process(const Mesh_data& data)
{
  const auto start = Clock::now();
  const SI::Energy_and_mass em = data.matrices(0.);
  Solver solver;
  SI::Factored_matrix<Solver> factored(solver);
  SI::Eigen_solve_result r = SI::smallest_eigenpair(em.energy, em.mass, factored, SI::Eigen_solve_options());
  Single_result result;
  result.ms = ms_since(start);
  result.eigenvalue = r.eigenvalue;
  result.vector.swap(r.vector);
  return result;
}

// The edges between parts of PT-Scotch's partition of the component's
// vertex graph into `parts` parts, on this process alone.
std::size_t ptscotch_cut(const Mesh_data& data, int parts)
{
  const SI::Component& comp = data.component();
  const PetscInt n = static_cast<PetscInt>(comp.vertices.size());
  std::vector<std::vector<PetscInt> > neighbours(comp.vertices.size());
  PetscInt entries = 0;
  for(std::size_t row = 0; row < comp.vertices.size(); ++row)
  {
    for(std::size_t corner : data.m.fan(comp.vertices[row]))
      for(std::size_t other : {SI::Indexed_mesh::next_corner(corner), SI::Indexed_mesh::previous_corner(corner)})
        neighbours[row].push_back(static_cast<PetscInt>(data.comps.local_index[data.m.vertex_of_corner(other)]));
    std::sort(neighbours[row].begin(), neighbours[row].end());
    neighbours[row].erase(std::unique(neighbours[row].begin(), neighbours[row].end()), neighbours[row].end());
    entries += static_cast<PetscInt>(neighbours[row].size());
  }
  PetscInt *offsets, *columns;  // PETSc's own arrays: the adjacency matrix frees them
  PetscMalloc1(n + 1, &offsets);
  PetscMalloc1(entries, &columns);
  offsets[0] = 0;
  for(PetscInt row = 0; row < n; ++row)
  {
    const std::vector<PetscInt>& list = neighbours[static_cast<std::size_t>(row)];
    std::copy(list.begin(), list.end(), columns + offsets[row]);
    offsets[row + 1] = offsets[row] + static_cast<PetscInt>(list.size());
  }
  Mat adjacency;
  MatCreateMPIAdj(PETSC_COMM_SELF, n, n, offsets, columns, nullptr, &adjacency);
  MatPartitioning partitioning;
  MatPartitioningCreate(PETSC_COMM_SELF, &partitioning);
  MatPartitioningSetAdjacency(partitioning, adjacency);
  MatPartitioningSetType(partitioning, MATPARTITIONINGPTSCOTCH);
  MatPartitioningSetNParts(partitioning, parts);
  IS part_of_row;
  MatPartitioningApply(partitioning, &part_of_row);
  const PetscInt* part;
  ISGetIndices(part_of_row, &part);
  std::size_t cut = 0;
  for(PetscInt row = 0; row < n; ++row)
    for(PetscInt column : neighbours[static_cast<std::size_t>(row)])
      cut += (column > row && part[column] != part[row]) ? 1 : 0;
  ISRestoreIndices(part_of_row, &part);
  ISDestroy(&part_of_row);
  MatPartitioningDestroy(&partitioning);
  MatDestroy(&adjacency);
  return cut;
}

void print_peaks(int rank, int size)
{
  std::vector<double> peaks(static_cast<std::size_t>(size));
  const double peak = proc_status_mb("VmHWM:");
  MPI_Gather(&peak, 1, MPI_DOUBLE, peaks.data(), 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  if(rank != 0) return;
  std::printf("  peak MB per rank:");
  for(double p : peaks) std::printf(" %.0f", p);
  std::printf("\n");
}

} // namespace

int main(int argc, char** argv)
{
  SlepcInitialize(&argc, &argv, nullptr, nullptr);
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  bool single = false, compare = false, partition_cut = false;
  SI::Distributed_eigen_solve_options options;
  for(int i = 2; i < argc; ++i)
  {
    single = single || std::strcmp(argv[i], "--single") == 0;
    compare = compare || std::strcmp(argv[i], "--compare") == 0;
    partition_cut = partition_cut || std::strcmp(argv[i], "--partition-cut") == 0;
    options.slepc_lobpcg = options.slepc_lobpcg || std::strcmp(argv[i], "--slepc-lobpcg") == 0;
    if(i + 1 < argc && std::strcmp(argv[i], "--regauge-tolerance") == 0) options.regauge_tolerance = std::atof(argv[i + 1]);
    if(i + 1 < argc && std::strcmp(argv[i], "--regauge-iterations") == 0) options.regauge_iterations = std::atoi(argv[i + 1]);
  }
  {
    std::unique_ptr<Mesh_data> data;
    int ok = 1;
    const auto start = Clock::now();
    if(rank == 0)
    {
      Mesh mesh;
      ok = argc >= 2 && CGAL::IO::read_polygon_mesh(argv[1], mesh) && !is_empty(mesh);
      if(ok)
      {
        const double read_ms = ms_since(start);
        const auto setup = Clock::now();
        data.reset(new Mesh_data(mesh));
        std::printf("%s  ranks %d  vertices %zu  faces %zu  read %.0f ms  tangent spaces and connection %.0f ms\n",
                    argv[1], size, data->component().vertices.size(), data->component().faces.size(), read_ms, ms_since(setup));
      }
      else
        std::fprintf(stderr, "usage: benchmark_distributed_field MESH [--single] [--compare] [--partition-cut] [--slepc-lobpcg]\n"
                           "       [--regauge-tolerance R] [--regauge-iterations K] [PETSc options]\n");
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    if(ok && single && rank == 0)
    {
      const Single_result r = single_process(*data);
      std::printf("  single process: eigenvalue %.15g  %.0f ms  singular faces %zu\n", r.eigenvalue, r.ms,
                  data->singular_faces(r.vector).size());
    }
    if(ok && !single)
    {
      SI::Assembly_source source;
      if(rank == 0) source = {&data->m, &data->ts, &data->con, &data->component(), &data->comps.local_index};
      const auto t0 = Clock::now();
      SI::Distributed_matrices matrices = SI::assemble_distributed(PETSC_COMM_WORLD, source, 0.);
      const double assembly_ms = ms_since(t0);
      const auto t1 = Clock::now();
      SI::Distributed_eigen_solve_result r =
        SI::distributed_smallest_eigenpair<Solver>(matrices.energy, matrices.mass, options);
      const double solve_ms = ms_since(t1);
      const auto t2 = Clock::now();
      const SI::Complex_vector x = r.converged ? SI::gather_on_first_process(r.vector) : SI::Complex_vector();
      const double gather_ms = ms_since(t2);
      if(r.vector) VecDestroy(&r.vector);
      matrices.destroy();
      if(rank == 0)
        std::printf("  distributed: eigenvalue %.15g  converged %d  iterations %ld  assembly %.0f ms  solve %.0f ms  "
                    "gather %.0f ms  total %.0f ms  cut edges %zu  singular faces %zu\n",
                    r.eigenvalue, int(r.converged), long(r.iterations), assembly_ms, solve_ms, gather_ms,
                    assembly_ms + solve_ms + gather_ms, matrices.cut_edges,
                    r.converged ? data->singular_faces(x).size() : std::size_t(0));
      print_peaks(rank, size);
      if(partition_cut && rank == 0)
        std::printf("  edge cut into %d parts: breadth-first ranges %zu, PT-Scotch %zu\n", size, matrices.cut_edges,
                    ptscotch_cut(*data, size));
      if(compare && rank == 0 && r.converged)
      {
        const Single_result s = single_process(*data);
        const std::vector<std::size_t> mine = data->singular_faces(x), theirs = data->singular_faces(s.vector);
        std::vector<std::size_t> differing;
        std::set_symmetric_difference(mine.begin(), mine.end(), theirs.begin(), theirs.end(), std::back_inserter(differing));
        std::printf("  single process: eigenvalue %.15g  %.0f ms  relative difference %.2e  singular faces not in both %zu\n",
                    s.eigenvalue, s.ms, std::abs(r.eigenvalue - s.eigenvalue) / s.eigenvalue, differing.size());
      }
    }
    else
      print_peaks(rank, size);
  }
  SlepcFinalize();
  return 0;
}
