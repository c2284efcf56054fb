// The program on a point set (.xyz, .pts, or a PLY without faces), compiled in
// point_set_run.cpp: which files are point sets, and the whole run on one.

#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_POINT_SET_RUN_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_POINT_SET_RUN_H

#include <string>

struct Options;
class Progress;
struct Program_timings;
class Output_files;
struct Polygon_soup;

namespace point_set_run {

// The file's extension, in lower case ("" without one).
std::string extension_of(const std::string& path);

// Whether the file is read as a point set whatever it holds (.xyz, .pts).
bool is_point_set_file(const std::string& path);

// Read, compute, write, report; the program's exit status. `soup`: the PLY
// read by the program's reader, without faces (null for .xyz and .pts).
int run(const Options& o, Progress& progress, Program_timings& timings, Output_files& outputs,
        const Polygon_soup* soup = nullptr);

} // namespace point_set_run

#endif // SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_POINT_SET_RUN_H
