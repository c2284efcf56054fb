// A headless picture of a direction field: a small software rasterizer that
// draws the shaded mesh, the n directions at evenly spread vertices, and the
// singular faces (red: positive index, blue: negative), and writes a PNG with
// no library beyond the standard one. Used by the command-line program; not
// part of the package's API.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_PNG_SNAPSHOT_H
#define SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_PNG_SNAPSHOT_H

#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace png_snapshot {

// the package's 3-vector toolkit
typedef CGAL::Surface_mesh_direction_fields::internal::Vec3 V3;
using CGAL::Surface_mesh_direction_fields::internal::cross;
using CGAL::Surface_mesh_direction_fields::internal::dot;
using CGAL::Surface_mesh_direction_fields::internal::norm;
using CGAL::Surface_mesh_direction_fields::internal::operator+;
using CGAL::Surface_mesh_direction_fields::internal::operator-;
using CGAL::Surface_mesh_direction_fields::internal::operator*;
inline V3 unit(const V3& a) { return CGAL::Surface_mesh_direction_fields::internal::normalized(a); }

struct Scene
{
  std::vector<V3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<V3> directions;       // one unit tangent vector per vertex (zero: none)
  std::vector<int> face_index;      // integer index k per face (0: regular)
  std::vector<std::vector<V3> > polylines;  // streamlines; when given, drawn instead of the glyphs
  int degree = 1;
};

// --- PNG writing: deflate with zlib when SMDF_PNG_WITH_ZLIB is defined (the
// CMake build does it when it finds zlib), zlib "stored" blocks otherwise.
#ifdef SMDF_PNG_WITH_ZLIB
#include <zlib.h>
#endif
inline std::uint32_t crc32(const unsigned char* data, std::size_t n, std::uint32_t crc = 0)
{
  static std::uint32_t table[256];
  static bool init = false;
  if(!init)
  {
    for(std::uint32_t i = 0; i < 256; ++i)
    {
      std::uint32_t c = i;
      for(int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[i] = c;
    }
    init = true;
  }
  crc = ~crc;
  for(std::size_t i = 0; i < n; ++i) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

inline void put32(std::vector<unsigned char>& out, std::uint32_t v)
{
  for(int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(v >> s));
}

inline void chunk(std::ofstream& os, const char* type, const std::vector<unsigned char>& data)
{
  std::vector<unsigned char> buf;
  put32(buf, static_cast<std::uint32_t>(data.size()));
  buf.insert(buf.end(), type, type + 4);
  buf.insert(buf.end(), data.begin(), data.end());
  const std::uint32_t crc = crc32(buf.data() + 4, buf.size() - 4);
  put32(buf, crc);
  os.write(reinterpret_cast<const char*>(buf.data()), static_cast<std::streamsize>(buf.size()));
}

// A zlib stream of "stored" (uncompressed) blocks: no library needed.
inline std::vector<unsigned char> stored_zlib_stream(const std::vector<unsigned char>& raw)
{
  std::vector<unsigned char> z = {0x78, 0x01};
  std::uint32_t a = 1, b = 0;
  for(unsigned char c : raw) { a = (a + c) % 65521; b = (b + a) % 65521; }
  for(std::size_t pos = 0; pos < raw.size(); pos += 65535)
  {
    const std::size_t len = (std::min)(std::size_t(65535), raw.size() - pos);
    z.push_back(pos + len == raw.size() ? 1 : 0);
    z.push_back(static_cast<unsigned char>(len & 0xFF));
    z.push_back(static_cast<unsigned char>(len >> 8));
    z.push_back(static_cast<unsigned char>(~len & 0xFF));
    z.push_back(static_cast<unsigned char>((~len >> 8) & 0xFF));
    z.insert(z.end(), raw.begin() + static_cast<long>(pos), raw.begin() + static_cast<long>(pos + len));
  }
  put32(z, (b << 16) | a);
  return z;
}

inline bool write_png(const std::string& path, int w, int h, const std::vector<unsigned char>& rgb)
{
  std::ofstream os(path, std::ios::binary);
  if(!os) return false;
  const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  os.write(reinterpret_cast<const char*>(signature), 8);
  std::vector<unsigned char> ihdr;
  put32(ihdr, static_cast<std::uint32_t>(w));
  put32(ihdr, static_cast<std::uint32_t>(h));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB
  chunk(os, "IHDR", ihdr);

  std::vector<unsigned char> raw;  // filter byte 0 before each row
  for(int y = 0; y < h; ++y)
  {
    raw.push_back(0);
    raw.insert(raw.end(), rgb.begin() + 3 * w * y, rgb.begin() + 3 * w * (y + 1));
  }
#ifdef SMDF_PNG_WITH_ZLIB
  // compressed with zlib when the build found it (about 50 times smaller)
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<unsigned char> z(size);
  if(compress2(z.data(), &size, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK) return false;
  z.resize(size);
#else
  std::vector<unsigned char> z = stored_zlib_stream(raw);
#endif
  chunk(os, "IDAT", z);
  chunk(os, "IEND", {});
  return static_cast<bool>(os);
}

// --- rendering
class Canvas
{
public:
  int w, h;
  std::vector<unsigned char> rgb;
  std::vector<double> depth;  // larger is closer
  Canvas(int w_, int h_) : w(w_), h(h_), rgb(3 * w_ * h_, 255), depth(w_ * h_, -std::numeric_limits<double>::infinity()) {}

  void set(int x, int y, const std::array<unsigned char, 3>& c)
  {
    if(x < 0 || y < 0 || x >= w || y >= h) return;
    for(int k = 0; k < 3; ++k) rgb[3 * (y * w + x) + k] = c[k];
  }

  // Filled triangle in screen space (x, y, depth), flat color, depth-tested.
  void triangle(const V3& a, const V3& b, const V3& c, const std::array<unsigned char, 3>& col)
  {
    const int x0 = (std::max)(0, static_cast<int>(std::floor((std::min)({a[0], b[0], c[0]}))));
    const int x1 = (std::min)(w - 1, static_cast<int>(std::ceil((std::max)({a[0], b[0], c[0]}))));
    const int y0 = (std::max)(0, static_cast<int>(std::floor((std::min)({a[1], b[1], c[1]}))));
    const int y1 = (std::min)(h - 1, static_cast<int>(std::ceil((std::max)({a[1], b[1], c[1]}))));
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if(std::abs(area) < 1e-12) return;
    for(int y = y0; y <= y1; ++y)
      for(int x = x0; x <= x1; ++x)
      {
        const double px = x + 0.5, py = y + 0.5;
        const double w0 = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area;
        const double w1 = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area;
        const double w2 = 1. - w0 - w1;
        if(w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double z = w0 * a[2] + w1 * b[2] + w2 * c[2];
        if(z <= depth[y * w + x]) continue;
        depth[y * w + x] = z;
        set(x, y, col);
      }
  }

  // Line drawn over surfaces that are not in front of it (depth with tolerance).
  void line(const V3& a, const V3& b, const std::array<unsigned char, 3>& col, double tolerance)
  {
    const int steps = static_cast<int>(std::ceil((std::max)(std::abs(b[0] - a[0]), std::abs(b[1] - a[1])))) + 1;
    for(int i = 0; i <= steps; ++i)
    {
      const double t = static_cast<double>(i) / steps;
      const int x = static_cast<int>(a[0] + t * (b[0] - a[0]));
      const int y = static_cast<int>(a[1] + t * (b[1] - a[1]));
      if(x < 0 || y < 0 || x >= w || y >= h) continue;
      const double z = a[2] + t * (b[2] - a[2]);
      if(z + tolerance < depth[y * w + x]) continue;
      set(x, y, col);
    }
  }

  void disc(const V3& c, double r, const std::array<unsigned char, 3>& col)
  {
    for(int y = static_cast<int>(c[1] - r); y <= static_cast<int>(c[1] + r); ++y)
      for(int x = static_cast<int>(c[0] - r); x <= static_cast<int>(c[0] + r); ++x)
        if((x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) <= r * r) set(x, y, col);
  }
};

// Renders the scene seen from `view` (a direction towards the camera) and writes it.
inline bool render(const Scene& s, const std::string& path, int width = 1024, int height = 1024,
                   V3 view = {0.55, 0.35, 0.76})
{
  if(s.points.empty() || s.triangles.empty()) return false;
  V3 lo = s.points[0], hi = s.points[0];
  for(const V3& p : s.points)
    for(int k = 0; k < 3; ++k) { lo[k] = (std::min)(lo[k], p[k]); hi[k] = (std::max)(hi[k], p[k]); }
  const V3 center = 0.5 * (lo + hi);
  const double radius = 0.5 * norm(hi - lo);
  view = unit(view);
  V3 up0 = {0, 1, 0};
  if(std::abs(dot(up0, view)) > 0.95) up0 = {0, 0, 1};
  const V3 right = unit(cross(up0, view));
  const V3 up = cross(view, right);
  const double scale = 0.48 * (std::min)(width, height) / radius;
  auto project = [&](const V3& p) {
    const V3 q = p - center;
    return V3{0.5 * width + scale * dot(q, right), 0.5 * height - scale * dot(q, up), dot(q, view) * scale};
  };

  Canvas canvas(width, height);
  std::vector<V3> screen(s.points.size());
  for(std::size_t i = 0; i < s.points.size(); ++i) screen[i] = project(s.points[i]);

  // Vertex normals for rotating the directions; mean edge length for their size.
  std::vector<V3> normals(s.points.size(), V3{0, 0, 0});
  double edge_sum = 0.;
  const V3 light = unit(view + V3{0.2, 0.5, 0.1});
  for(std::size_t f = 0; f < s.triangles.size(); ++f)
  {
    const auto& t = s.triangles[f];
    const V3 n = cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]]);
    for(int c = 0; c < 3; ++c) normals[t[c]] = normals[t[c]] + n;
    for(int c = 0; c < 3; ++c) edge_sum += norm(s.points[t[(c + 1) % 3]] - s.points[t[c]]);
    const V3 nu = unit(n);
    const double shade = 0.35 + 0.65 * std::abs(dot(nu, light));
    std::array<unsigned char, 3> col = {static_cast<unsigned char>(205 * shade), static_cast<unsigned char>(210 * shade),
                                        static_cast<unsigned char>(220 * shade)};
    const int k = f < s.face_index.size() ? s.face_index[f] : 0;
    if(k > 0) col = {230, 40, 40};
    if(k < 0) col = {40, 80, 230};
    canvas.triangle(screen[t[0]], screen[t[1]], screen[t[2]], col);
  }
  const double mean_edge = edge_sum / (3. * s.triangles.size());

  // One glyph per screen cell of `cell` pixels, at the vertex closest to the
  // camera in that cell, if visible.
  const int cell = 14;
  const int gw = width / cell + 1, gh = height / cell + 1;
  std::vector<long> chosen(static_cast<std::size_t>(gw * gh), -1);
  for(std::size_t i = 0; i < s.points.size(); ++i)
  {
    const V3& p = screen[i];
    if(p[0] < 0 || p[1] < 0 || p[0] >= width || p[1] >= height) continue;
    if(i >= s.directions.size() || dot(s.directions[i], s.directions[i]) == 0.) continue;
    const int x = static_cast<int>(p[0]), y = static_cast<int>(p[1]);
    if(p[2] + 2. < canvas.depth[y * width + x]) continue;  // hidden
    long& c = chosen[(y / cell) * gw + x / cell];
    if(c < 0 || screen[static_cast<std::size_t>(c)][2] < p[2]) c = static_cast<long>(i);
  }
  const double glyph = (std::min)(0.45 * cell / scale, 1.5 * mean_edge);
  const double pi = 3.14159265358979323846;
  for(const auto& polyline : s.polylines)
    for(std::size_t i = 0; i + 1 < polyline.size(); ++i)
      canvas.line(project(polyline[i]), project(polyline[i + 1]), {20, 60, 70}, 3.);
  for(long ci : chosen)
  {
    if(ci < 0 || !s.polylines.empty()) continue;
    const std::size_t i = static_cast<std::size_t>(ci);
    const V3 n = unit(normals[i]);
    const V3 d = s.directions[i];
    const V3 e = cross(n, d);
    for(int k = 0; k < s.degree; ++k)
    {
      const double a = 2. * pi * k / s.degree;
      const V3 dk = std::cos(a) * d + std::sin(a) * e;
      const V3 tip = s.points[i] + glyph * dk;
      // a vector field (n = 1) gets a two-sided stroke with a dark head
      canvas.line(screen[i], project(tip), {20, 20, 20}, 3.);
      if(s.degree == 1)
        canvas.line(screen[i], project(s.points[i] + (-0.6 * glyph) * dk), {110, 110, 110}, 3.);
    }
  }
  // Mark singular faces so that they are seen even when smaller than a pixel.
  for(std::size_t f = 0; f < s.triangles.size() && f < s.face_index.size(); ++f)
  {
    if(s.face_index[f] == 0) continue;
    const auto& t = s.triangles[f];
    const V3 c = (1. / 3.) * (screen[t[0]] + screen[t[1]] + screen[t[2]]);
    const int x = static_cast<int>(c[0]), y = static_cast<int>(c[1]);
    if(x < 0 || y < 0 || x >= width || y >= height || c[2] + 2. < canvas.depth[y * width + x]) continue;
    canvas.disc(c, 6., s.face_index[f] > 0 ? std::array<unsigned char, 3>{220, 30, 30}
                                           : std::array<unsigned char, 3>{30, 70, 220});
  }
  return write_png(path, width, height, canvas.rgb);
}

} // namespace png_snapshot

#endif
