// Checks for the test programs that stay active in every build type (unlike
// assert, which NDEBUG removes), and a one-line summary that CTest logs show.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_TEST_SUPPORT_H
#define SURFACE_MESH_DIRECTION_FIELDS_TEST_SUPPORT_H

#include <cstdlib>
#include <iostream>
#include <string>

// Whether a check was left out because a shared mesh is missing: the test
// then reports SKIP to CTest (SKIP_RETURN_CODE 77) unless a check failed.
inline bool& shared_mesh_missing()
{
  static bool missing = false;
  return missing;
}

class Test_report
{
  std::string m_name;
  int m_passed = 0, m_failed = 0;

public:
  explicit Test_report(std::string name) : m_name(std::move(name)) {}

  bool check(bool ok, const std::string& what)
  {
    if(ok) ++m_passed;
    else { ++m_failed; std::cerr << "FAILED: " << what << std::endl; }
    return ok;
  }

  int failed() const { return m_failed; }

  int finish() const
  {
    std::cout << m_name << ": " << m_passed << " checks passed, " << m_failed << " failed" << std::endl;
    if(m_failed != 0) return EXIT_FAILURE;
    if(shared_mesh_missing())
    {
      std::cout << m_name << ": SKIP (checks on the shared meshes left out: ../shared/data/meshes)" << std::endl;
      return 77;
    }
    return EXIT_SUCCESS;
  }
};

// Directory of the shared meshes (../shared/data/meshes seen from the project
// root), passed by CMake; empty when it is absent.
#ifndef SMDF_SHARED_MESH_DIR
#define SMDF_SHARED_MESH_DIR ""
#endif

#include <fstream>

// Full path of a shared mesh, or "" (with a message) when ../shared is absent.
inline std::string shared_mesh_path(const std::string& name)
{
  const std::string dir = SMDF_SHARED_MESH_DIR;
  if(dir.empty())
  {
    std::cout << "SKIPPED " << name << ": ../shared/data/meshes not found" << std::endl;
    shared_mesh_missing() = true;
    return "";
  }
  const std::string path = dir + "/" + name;
  std::ifstream probe(path);
  if(!probe)
  {
    std::cout << "SKIPPED " << name << ": not in " << dir << std::endl;
    shared_mesh_missing() = true;
    return "";
  }
  return path;
}

// The closed and the open shared meshes (../shared/data/meshes/README.md).
inline const char* const* closed_shared_meshes()
{
  static const char* const names[] = {"sphere_oded.off", "torus_oded.off", "spot.off", "eight.off", "fertility.off",
                                      "fandisk.off", "cow.off", "bones.off", "nefertiti.off", "nefertiti_sub4.off", nullptr};
  return names;
}
inline const char* const* open_shared_meshes()
{
  static const char* const names[] = {"stanford_bunny_open.off", "camelhead.off", "blade.off", "plane_holes.off", nullptr};
  return names;
}

#endif
