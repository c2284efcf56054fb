// The options of the command-line program direction_field: what each one
// means is in the usage text below and in the README ("Command line").
#ifndef SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_COMMAND_LINE_OPTIONS_H
#define SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_COMMAND_LINE_OPTIONS_H

#include <CGAL/config.h>

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

struct Options
{
  std::string mesh;
  int degree = 4;
  double s = 0.;
  std::string directions, singularities, png, json_file;
  std::string vtk, ply, rosy, ffield, singularity_list, streamlines;
  bool json = false;
  unsigned int seed = 0;
  unsigned int max_iterations = 1000;
  double tolerance = 1e-10;
  std::string align = "none", guidance, constrain_boundary = "none";
  bool lambda_given = false, weight_given = false;
  double lambda = 0., weight = 0.5;
  bool eigenvalue_bound = false;
  std::string curvature_estimate = "quadric-fit";
  double feature_angle = -1.;  // negative: no feature alignment
};

// A problem with the input or the options: reported on one line, exit status 1.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

inline const char* const usage =
  "usage: direction_field [MESH] [--degree N] [--s S] [--directions FILE] [--singularities FILE]\n"
  "                       [--json] [--json-file FILE] [--png FILE] [--seed N] [--max-iterations N]\n"
  "                       [--tolerance T] [--align none|curvature|min-curvature|max-curvature]\n"
  "                       [--guidance FILE] [--lambda L | --alignment-weight T]\n"
  "                       [--constrain-boundary tangent|normal] [--eigenvalue-bound]\n"
  "                       [--curvature-estimate quadric-fit|hopf] [--feature-angle DEG]\n"
  "                       [--vtk FILE] [--ply FILE] [--rosy FILE] [--ffield FILE] [--singularity-list FILE]\n"
  "                       [--streamlines FILE]\n";

template <typename T>
T parse_number(const std::string& option, const std::string& text)
{
  std::istringstream is(text);
  T value;
  char rest;
  if(!(is >> value) || (is >> rest))
    throw Usage_error("option " + option + " expects a number, got '" + text + "'");
  return value;
}

// `default_mesh` is used when no MESH is given.
inline Options parse_options(int argc, char** argv, const std::string& default_mesh)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Usage_error("option " + a + " expects a value");
      return argv[++i];
    };
    if(a == "--help" || a == "-h") { std::cout << usage; std::exit(EXIT_SUCCESS); }
    else if(a == "--degree") o.degree = parse_number<int>(a, value());
    else if(a == "--s") o.s = parse_number<double>(a, value());
    else if(a == "--directions") o.directions = value();
    else if(a == "--singularities") o.singularities = value();
    else if(a == "--png") o.png = value();
    else if(a == "--json") o.json = true;
    else if(a == "--json-file") o.json_file = value();
    else if(a == "--seed") o.seed = parse_number<unsigned int>(a, value());
    else if(a == "--max-iterations") o.max_iterations = parse_number<unsigned int>(a, value());
    else if(a == "--tolerance") o.tolerance = parse_number<double>(a, value());
    else if(a == "--align") o.align = value();
    else if(a == "--guidance") o.guidance = value();
    else if(a == "--lambda") { o.lambda = parse_number<double>(a, value()); o.lambda_given = true; }
    else if(a == "--alignment-weight") { o.weight = parse_number<double>(a, value()); o.weight_given = true; }
    else if(a == "--constrain-boundary") o.constrain_boundary = value();
    else if(a == "--eigenvalue-bound") o.eigenvalue_bound = true;
    else if(a == "--curvature-estimate") o.curvature_estimate = value();
    else if(a == "--feature-angle") o.feature_angle = parse_number<double>(a, value());
    else if(a == "--vtk") o.vtk = value();
    else if(a == "--ply") o.ply = value();
    else if(a == "--rosy") o.rosy = value();
    else if(a == "--ffield") o.ffield = value();
    else if(a == "--singularity-list") o.singularity_list = value();
    else if(a == "--streamlines") o.streamlines = value();
    else if(!a.empty() && a[0] == '-' && a != "-") throw Usage_error("unknown option " + a);
    else if(o.mesh.empty()) o.mesh = a;
    else throw Usage_error("more than one mesh given ('" + o.mesh + "' and '" + a + "')");
  }
  if(o.mesh.empty())
    o.mesh = default_mesh;
  if(o.align != "none" && o.align != "curvature" && o.align != "min-curvature" && o.align != "max-curvature")
    throw Usage_error("--align expects none, curvature, min-curvature or max-curvature, got '" + o.align + "'");
  if(o.constrain_boundary != "none" && o.constrain_boundary != "tangent" && o.constrain_boundary != "normal")
    throw Usage_error("--constrain-boundary expects tangent or normal, got '" + o.constrain_boundary + "'");
  if(o.feature_angle != -1. && !(o.feature_angle > 0. && o.feature_angle < 180.))
    throw Usage_error("--feature-angle expects an angle in degrees in (0, 180), got " + std::to_string(o.feature_angle));
  if(o.curvature_estimate != "quadric-fit" && o.curvature_estimate != "hopf")
    throw Usage_error("--curvature-estimate expects quadric-fit or hopf, got '" + o.curvature_estimate + "'");
  if(o.lambda_given && o.weight_given)
    throw Usage_error("give either --lambda or --alignment-weight, not both");
  return o;
}

#endif
