// The program's text inputs other than the mesh: reading them whole, and the
// --guidance file (one vector per vertex of a mesh file, or per point).

#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_GUIDANCE_FILE_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_GUIDANCE_FILE_H

#include "command_line_options.h"
#include "file_io/read_polygon_soup.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

// The text of an input file other than the mesh (folders, devices and pipes
// nobody writes refused as the mesh reader refuses them), without a UTF-8
// byte order mark.
inline std::string text_file(const std::string& path, const char* what)
{
  std::string text = soup_reading::read_whole_file(path, what);
  if(text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  return text;
}

// --guidance: 'x y z' per line (blank lines skipped), `count` of them, one per
// `element` ("vertices" of the mesh file, or "points").
inline std::vector<std::array<double, 3> > read_guidance_file(const std::string& path, std::size_t count,
                                                              const char* elements)
{
  std::istringstream in(text_file(path, "a guidance file"));
  std::vector<std::array<double, 3> > vectors;
  std::string line;
  while(std::getline(in, line))
  {
    if(line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream is(line);
    double x, y, z;
    if(!(is >> x >> y >> z) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw Usage_error("line " + std::to_string(vectors.size() + 1) + " of '" + path +
                        "' is not three finite numbers");
    vectors.push_back({x, y, z});
  }
  if(vectors.size() != count)
    throw Usage_error("'" + path + "' has " + std::to_string(vectors.size()) + " vectors for " +
                      std::to_string(count) + " " + elements);
  return vectors;
}

#endif // SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_GUIDANCE_FILE_H
