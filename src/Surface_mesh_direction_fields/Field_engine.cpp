// The compiled engines (fields on vertices, on faces and on point sets) of the default solver, for programs that link the CMake
// target CGAL::Surface_mesh_direction_fields_compiled (which defines
// CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION for them): they then
// compile only the mesh plumbing of Globally_optimal_direction_field (see the
// README and the manual, "Compiling Faster").
#include <CGAL/Surface_mesh_direction_fields/Globally_optimal_direction_field.h>
#include <CGAL/Surface_mesh_direction_fields/globally_optimal_face_directions.h>
#include <CGAL/Surface_mesh_direction_fields/globally_optimal_point_set_directions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Field_engine_impl.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Face_field_engine_impl.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Point_set_engine_impl.h>
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#include <CGAL/Surface_mesh_direction_fields/Cholmod_supernodal_solver.h>
#endif

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template class Field_engine<Default_direction_field_solver>;
template class Face_field_engine<Default_direction_field_solver>;
template struct Point_set_engine<Default_direction_field_solver>;

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL
