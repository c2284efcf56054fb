// Numbers in the one-line messages of the program and the Python module,
// compactly ("1e+09", "0.5"), as the library writes them in its own.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_MESSAGES_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_MESSAGES_H

#include <cstdio>
#include <string>

inline std::string compact(double x)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

#endif // SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_MESSAGES_H
