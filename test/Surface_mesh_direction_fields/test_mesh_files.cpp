// The command-line program's mesh reader (read_polygon_soup.h) against CGAL's
// own reader (CGAL::IO::read_polygon_soup): the same points, bit for bit, and
// the same polygons, on the shared meshes and on files of every format and
// encoding written here by CGAL's writers. No timing is checked here.
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include "png_snapshot.h"
#include "file_io/read_polygon_soup.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;

namespace {

struct Cgal_soup
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
};

bool same_soup(const Polygon_soup& ours, const Cgal_soup& cgal, std::string& why)
{
  if(ours.points.size() != cgal.points.size())
  { why = std::to_string(ours.points.size()) + " points, CGAL " + std::to_string(cgal.points.size()); return false; }
  if(ours.number_of_polygons() != cgal.polygons.size())
  { why = std::to_string(ours.number_of_polygons()) + " polygons, CGAL " + std::to_string(cgal.polygons.size()); return false; }
  for(std::size_t i = 0; i < cgal.points.size(); ++i)
    for(int c = 0; c < 3; ++c)
      if(ours.points[i][c] != cgal.points[i][c])
      {
        std::ostringstream os;
        os << std::setprecision(17) << "point " << i << " differs: " << ours.points[i][c] << " and " << cgal.points[i][c];
        why = os.str();
        return false;
      }
  for(std::size_t f = 0; f < cgal.polygons.size(); ++f)
    if(!std::equal(ours.begin(f), ours.end(f), cgal.polygons[f].begin(), cgal.polygons[f].end()))
    { why = "polygon " + std::to_string(f) + " differs"; return false; }
  return true;
}

void compare_with_cgal(const std::string& path, Test_report& report)
{
  Cgal_soup cgal;
  const bool cgal_read = CGAL::IO::read_polygon_soup(path, cgal.points, cgal.polygons, CGAL::parameters::verbose(false));
  report.check(cgal_read, "CGAL reads " + path);
  std::string why;
  const Polygon_soup ours = read_polygon_soup(path);
  const bool same = same_soup(ours, cgal, why);
  report.check(same, "same soup as CGAL's reader on " + path + " (" + why + ")");
}

// A soup with coordinates that need all 17 digits, a quad and a pentagon.
Cgal_soup awkward_soup()
{
  Cgal_soup s;
  CGAL::Surface_mesh<Point_3> m;
  make_jittered_ellipsoid(m, 2, 1., 0.7, 0.4, 0.3, 3);
  for(const auto& p : m.points()) s.points.push_back(p);
  for(auto f : m.faces())
  {
    std::vector<std::size_t> poly;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) poly.push_back(std::size_t(v));
    s.polygons.push_back(poly);
  }
  s.polygons.push_back({0, 1, 2, 3});
  s.polygons.push_back({4, 5, 6, 7, 8});
  return s;
}

} // namespace

// The picture's views: a sheet (a tilted 10 x 1 x 0.01 strip) is seen from
// both sides at most 50 degrees from its normal, not at a graze; a rounder
// shape keeps the tetrahedron's four views.
void check_picture_views(Test_report& report)
{
  using namespace png_snapshot;  // its vector operators
  const V3 normal = png_snapshot::unit(V3{0.3, -0.2, 1.});
  const V3 along = png_snapshot::unit(png_snapshot::cross(normal, V3{1., 0., 0.}));
  const V3 across = png_snapshot::cross(normal, along);
  std::vector<V3> strip, block;
  for(int i = 0; i <= 100; ++i)
    for(int j = 0; j <= 10; ++j)
      for(int k = 0; k <= 1; ++k)
      {
        strip.push_back((0.1 * i) * along + (0.1 * j) * across + (0.01 * k) * normal);
        block.push_back(V3{0.1 * i, 0.5 * j, 3. * k});
      }
  const png_snapshot::View_set sheet = png_snapshot::view_directions(strip);
  bool facing = true, both_sides[2] = {false, false};
  for(const V3& d : sheet.directions)
  {
    const double c = png_snapshot::dot(d, normal);
    facing = facing && std::abs(c) >= std::cos(0.88);
    both_sides[c > 0.] = true;
  }
  report.check(facing && both_sides[0] && both_sides[1] && std::abs(png_snapshot::dot(sheet.up, normal)) < 1e-6,
               "a sheet is seen from both sides, within 50 degrees of its normal");
  const png_snapshot::View_set round = png_snapshot::view_directions(block);
  report.check(round.up[1] == 1. && std::abs(png_snapshot::dot(round.directions[0], round.directions[1]) + 1. / 3.) < 1e-12,
               "a shape that is not a sheet keeps the tetrahedron's views");
}

int main()
{
  Test_report report("test_mesh_files");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "smdf_test_mesh_files";
  std::filesystem::create_directories(dir);

  // Every writer of CGAL and every encoding it offers.
  const Cgal_soup soup = awkward_soup();
  const std::vector<std::pair<std::string, bool> > files = {
    {"soup.off", false}, {"soup.obj", false}, {"soup_ascii.ply", false}, {"soup_binary.ply", true},
    {"triangles_ascii.stl", false}, {"triangles_binary.stl", true}};
  for(const auto& [name, binary] : files)
  {
    const std::string path = (dir / name).string();
    Cgal_soup written = soup;
    if(name.find(".stl") != std::string::npos) written.polygons.resize(written.polygons.size() - 2);  // triangles only
    report.check(CGAL::IO::write_polygon_soup(path, written.points, written.polygons,
                                              CGAL::parameters::stream_precision(17).use_binary_mode(binary)),
                 "CGAL writes " + name);
    compare_with_cgal(path, report);
  }
  // Binary OFF as Geomview specifies it: after each face's indices, the number
  // of its colour values. CGAL 5.5's polygon-soup reader does not read that
  // number (it takes it for the next face's size), so this file is compared
  // with what was written, rounded to float as the format stores it.
  {
    const std::string path = (dir / "binary.off").string();
    std::ofstream os(path, std::ios::binary);
    auto int32 = [&](std::int32_t i) { for(int b = 3; b >= 0; --b) os.put(static_cast<char>((i >> (8 * b)) & 0xFF)); };
    auto float32 = [&](float x) { std::int32_t i; std::memcpy(&i, &x, 4); int32(i); };
    os << "OFF BINARY\n";
    int32(static_cast<std::int32_t>(soup.points.size()));
    int32(static_cast<std::int32_t>(soup.polygons.size()));
    int32(0);
    for(const Point_3& p : soup.points) { float32(float(p.x())); float32(float(p.y())); float32(float(p.z())); }
    for(const auto& poly : soup.polygons)
    {
      int32(static_cast<std::int32_t>(poly.size()));
      for(std::size_t v : poly) int32(static_cast<std::int32_t>(v));
      int32(0);
    }
    os.close();
    Cgal_soup expected;
    expected.polygons = soup.polygons;
    auto to_float = [](double x) { return static_cast<double>(static_cast<float>(x)); };
    for(const Point_3& p : soup.points) expected.points.emplace_back(to_float(p.x()), to_float(p.y()), to_float(p.z()));
    std::string why;
    const bool same = same_soup(read_polygon_soup(path), expected, why);
    report.check(same, "binary OFF read as written (" + why + ")");
  }
  // The shared meshes (skipped when the folder is absent).
  const std::string shared = SMDF_SHARED_MESH_DIR;
  if(!shared.empty() && std::filesystem::is_directory(shared))
  {
    for(const auto& entry : std::filesystem::directory_iterator(shared))
      if(entry.path().extension() == ".off") compare_with_cgal(entry.path().string(), report);
  }
  else
    std::cout << "NOTICE: no shared meshes; only the generated files were compared\n";
  if(report.failed() == 0) std::filesystem::remove_all(dir);
  else std::cout << "files kept in " << dir << "\n";
  // the picture's legend: indices as reduced fractions with their sign
  report.check(png_snapshot::index_label(1, 1) == "+1" && png_snapshot::index_label(-1, 1) == "-1" &&
                 png_snapshot::index_label(1, 2) == "+1/2" && png_snapshot::index_label(2, 4) == "+1/2" &&
                 png_snapshot::index_label(-1, 4) == "-1/4" && png_snapshot::index_label(4, 4) == "+1" &&
                 png_snapshot::index_label(-3, 6) == "-1/2",
               "legend labels: +1, -1, +1/2, -1/4 (reduced)");
  bool every_character_drawn = true;  // what draw_legend() writes, but the spaces
  for(char c : std::string("n = 0123456789 index: +-/ x no singularity features"))
    every_character_drawn = every_character_drawn && (c == ' ' || png_snapshot::glyph_rows(c) != nullptr);
  report.check(every_character_drawn, "the legend's font has every character the legend writes");
  check_picture_views(report);
  return report.finish();
}
