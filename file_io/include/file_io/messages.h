// Words and numbers that the program and the Python module both print:
// numbers in one-line messages compactly ("1e+09", "0.5"), as the library
// writes them in its own, and the names of what solved a component.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_MESSAGES_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_MESSAGES_H

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>

#include <cstdio>
#include <string>

inline std::string compact(double x)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// The names of Field_solve, as the program's JSON ("solves") and Python's `solves` give them.
inline const char* solve_name(CGAL::Surface_mesh_direction_fields::Field_solve solve)
{
  typedef CGAL::Surface_mesh_direction_fields::Field_solve Field_solve;
  return solve == Field_solve::EIGEN_SOLVE ? "eigen-solve" : solve == Field_solve::LINEAR_SOLVE ? "linear solve"
                                                                                                 : "parallel section";
}

#endif // SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_MESSAGES_H
