// A headless picture of a direction field: a small software rasterizer that
// draws the shaded mesh from four sides, the field (its lines, or the n
// directions at evenly spread vertices or faces), the singular faces or
// vertices (red: positive index, blue: negative) and a legend, and writes a PNG with no library
// beyond the standard one (and zlib when the build found it). Used by the command-line program; not
// part of the package's API.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_PNG_SNAPSHOT_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_PNG_SNAPSHOT_H

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace png_snapshot {

// The picture's own 3-vectors (the package keeps its vector math internal).
typedef std::array<double, 3> V3;
inline V3 operator+(const V3& a, const V3& b) { return V3{a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline V3 operator-(const V3& a, const V3& b) { return V3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline V3 operator*(double s, const V3& a) { return V3{s * a[0], s * a[1], s * a[2]}; }
inline double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(const V3& a) { return std::sqrt(dot(a, a)); }
inline V3 cross(const V3& a, const V3& b)
{
  return V3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// a / |a| (as 1 / |a| times a); the zero vector stays zero
inline V3 unit(const V3& a)
{
  const double length = norm(a);
  return length > 0. ? (1. / length) * a : a;
}

struct Scene
{
  std::vector<V3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<V3> directions;       // one unit tangent vector per vertex, or per face (zero: none)
  bool directions_on_faces = false;  // a field on faces: directions per triangle, drawn at its centre
  std::vector<int> face_index;      // integer index k per face (0: regular)
  std::vector<int> vertex_index;    // integer index k per vertex, for a field on faces (0: regular)
  std::vector<std::vector<V3> > polylines;  // streamlines; when given, drawn instead of the glyphs
  std::vector<std::array<std::size_t, 2> > feature_edges;  // the field follows them: drawn over it
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

inline void chunk(std::ostream& os, const char* type, const std::vector<unsigned char>& data)
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

inline bool write_png(std::ostream& os, int w, int h, const std::vector<unsigned char>& rgb)
{
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

// --- the legend's text: a 5 x 7 pixel font for the characters it needs

inline const unsigned char* glyph_rows(char c)
{
  static const struct { char c; unsigned char rows[7]; } font[] = {
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}}, {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}}, {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}}, {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}}, {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}}, {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'+', {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}}, {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
    {'/', {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00}}, {'=', {0x00, 0x00, 0x1F, 0x00, 0x1F, 0x00, 0x00}},
    {':', {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00}}, {'n', {0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11}},
    {'i', {0x04, 0x00, 0x0C, 0x04, 0x04, 0x04, 0x0E}}, {'d', {0x01, 0x01, 0x0D, 0x13, 0x11, 0x11, 0x0F}},
    {'e', {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E}}, {'x', {0x00, 0x00, 0x11, 0x0A, 0x04, 0x0A, 0x11}},
    {'o', {0x00, 0x00, 0x0E, 0x11, 0x11, 0x11, 0x0E}}, {'s', {0x00, 0x00, 0x0F, 0x10, 0x0E, 0x01, 0x1E}},
    {'g', {0x00, 0x00, 0x0F, 0x11, 0x0F, 0x01, 0x0E}}, {'u', {0x00, 0x00, 0x11, 0x11, 0x11, 0x13, 0x0D}},
    {'l', {0x0C, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}}, {'a', {0x00, 0x00, 0x0E, 0x01, 0x0F, 0x11, 0x0F}},
    {'r', {0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10}}, {'t', {0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06}},
    {'y', {0x00, 0x00, 0x11, 0x11, 0x0F, 0x01, 0x0E}}, {'f', {0x06, 0x09, 0x08, 0x1C, 0x08, 0x08, 0x08}}};
  for(const auto& g : font)
    if(g.c == c) return g.rows;
  return nullptr;  // a space
}

// Text at (x, y), its top left corner, each font pixel `size` pixels wide.
inline void text(Canvas& canvas, int x, int y, const std::string& s, int size, const std::array<unsigned char, 3>& col)
{
  for(char c : s)
  {
    if(const unsigned char* rows = glyph_rows(c))
      for(int r = 0; r < 7; ++r)
        for(int b = 0; b < 5; ++b)
          if(rows[r] & (0x10 >> b))
            for(int dy = 0; dy < size; ++dy)
              for(int dx = 0; dx < size; ++dx) canvas.set(x + b * size + dx, y + r * size + dy, col);
    x += 6 * size;
  }
}

inline std::array<unsigned char, 3> index_colour(int k)
{
  if(k > 0) return k == 1 ? std::array<unsigned char, 3>{225, 35, 35} : std::array<unsigned char, 3>{140, 0, 0};
  return k == -1 ? std::array<unsigned char, 3>{35, 75, 225} : std::array<unsigned char, 3>{0, 20, 130};
}

// --- one view of the scene in a panel of the picture

struct View
{
  V3 direction, right, up, centre;
  double scale = 1.;
  int x0 = 0, y0 = 0, size = 0;  // the panel

  V3 project(const V3& p) const
  {
    const V3 q = p - centre;
    return V3{x0 + 0.5 * size + scale * dot(q, right), y0 + 0.5 * size - scale * dot(q, up), dot(q, direction) * scale};
  }
};

// A view along `direction` framing the points tightly in the panel at (x0, y0).
// `up` is the direction shown upwards where the view allows.
inline View make_view(const std::vector<V3>& points, V3 direction, V3 up, int x0, int y0, int size)
{
  View v;
  v.direction = unit(direction);
  V3 up0 = up;
  if(std::abs(dot(up0, v.direction)) > 0.95) up0 = V3{up[2], up[0], up[1]};  // another axis
  v.right = unit(cross(up0, v.direction));
  v.up = cross(v.direction, v.right);
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for(const V3& p : points)
  {
    const double c[2] = {dot(p, v.right), dot(p, v.up)};
    for(int k = 0; k < 2; ++k) { lo[k] = (std::min)(lo[k], c[k]); hi[k] = (std::max)(hi[k], c[k]); }
  }
  const double extent = (std::max)({hi[0] - lo[0], hi[1] - lo[1], 1e-300});
  v.scale = 0.94 * size / extent;
  // the centre: the middle of the projected extent, at the points' mean depth
  V3 mean = {0, 0, 0};
  for(const V3& p : points) mean = mean + (1. / points.size()) * p;
  v.centre = (0.5 * (lo[0] + hi[0])) * v.right + (0.5 * (lo[1] + hi[1])) * v.up + dot(mean, v.direction) * v.direction;
  v.x0 = x0;
  v.y0 = y0;
  v.size = size;
  return v;
}

// The shaded triangles of one view (singular faces in their index colour).
inline void draw_surface(const Scene& s, const View& view, const std::vector<V3>& screen, Canvas& canvas)
{
  const V3 light = unit(view.direction + 0.2 * view.right + 0.5 * view.up);
  for(std::size_t f = 0; f < s.triangles.size(); ++f)
  {
    const auto& t = s.triangles[f];
    const V3 nu = unit(cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]]));
    const double shade = 0.35 + 0.65 * std::abs(dot(nu, light));
    std::array<unsigned char, 3> col = {static_cast<unsigned char>(205 * shade), static_cast<unsigned char>(210 * shade),
                                        static_cast<unsigned char>(220 * shade)};
    const int k = f < s.face_index.size() ? s.face_index[f] : 0;
    if(k != 0) col = index_colour(k);
    canvas.triangle(screen[t[0]], screen[t[1]], screen[t[2]], col);
  }
}

// An arrowhead on screen at `tip`, pointing along the unit screen direction
// `along`: two strokes of length about `size` back from the tip.
inline void draw_chevron(Canvas& canvas, const V3& tip, const V3& along, double size,
                         const std::array<unsigned char, 3>& colour)
{
  const V3 across = {-along[1], along[0], 0.};
  canvas.line(tip, tip + (-size) * along + (0.6 * size) * across, colour, 3.);
  canvas.line(tip, tip + (-size) * along + (-0.6 * size) * across, colour, 3.);
}

// Where the directions live (the vertices, or the triangles' centres for a
// field on faces) and the normals about which they turn.
struct Anchors
{
  std::vector<V3> points, normals;
};

// The n directions at anchors spread over the view (one per screen cell,
// the visible anchor closest to the camera).
inline void draw_glyphs(const Scene& s, const View& view, const Anchors& anchors, double mean_edge, Canvas& canvas)
{
  const int cell = 12;
  const int cells = view.size / cell + 1;
  std::vector<V3> screen(anchors.points.size());
  for(std::size_t i = 0; i < screen.size(); ++i) screen[i] = view.project(anchors.points[i]);
  std::vector<long> chosen(static_cast<std::size_t>(cells * cells), -1);
  for(std::size_t i = 0; i < anchors.points.size() && i < s.directions.size(); ++i)
  {
    const V3& p = screen[i];
    const int x = static_cast<int>(p[0]) - view.x0, y = static_cast<int>(p[1]) - view.y0;
    if(x < 0 || y < 0 || x >= view.size || y >= view.size || dot(s.directions[i], s.directions[i]) == 0.) continue;
    if(p[2] + 2. < canvas.depth[static_cast<std::size_t>((y + view.y0) * canvas.w + x + view.x0)]) continue;  // hidden
    long& c = chosen[static_cast<std::size_t>((y / cell) * cells + x / cell)];
    if(c < 0 || screen[static_cast<std::size_t>(c)][2] < p[2]) c = static_cast<long>(i);
  }
  const double glyph = (std::min)(0.42 * cell / view.scale, 1.5 * mean_edge);
  for(long ci : chosen)
  {
    if(ci < 0) continue;
    const std::size_t i = static_cast<std::size_t>(ci);
    const V3 d = s.directions[i], e = cross(unit(anchors.normals[i]), d);
    // a single direction is drawn across its anchor, as long as a cross is wide
    const V3 tail = s.degree == 1 ? view.project(anchors.points[i] - glyph * d) : screen[i];
    for(int k = 0; k < s.degree; ++k)
    {
      const double a = 2. * 3.14159265358979323846 * k / s.degree;
      const V3 dk = std::cos(a) * d + std::sin(a) * e;
      const V3 tip = view.project(anchors.points[i] + glyph * dk);
      canvas.line(tail, tip, {20, 20, 20}, 3.);
      const double length = std::hypot(tip[0] - tail[0], tip[1] - tail[1]);
      if(s.degree % 2 == 1 && length > 2.)  // odd n: the directions have a sign, an arrowhead shows it
        draw_chevron(canvas, tip, (1. / length) * (tip - tail), (s.degree == 1 ? 0.3 : 0.4) * length, {20, 20, 20});
    }
  }
}

// For a field of odd degree (its directions have a sign), a line is traced
// along the field: a small arrowhead every 40 pixels of its length on screen.
inline void draw_arrowheads(const std::vector<V3>& polyline, const View& view, Canvas& canvas)
{
  const double every = 40., size = 6.;
  double travelled = 0.5 * every;
  for(std::size_t i = 0; i + 1 < polyline.size(); ++i)
  {
    const V3 a = view.project(polyline[i]), b = view.project(polyline[i + 1]);
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    for(travelled += length; travelled >= every && length > 0.; travelled -= every)
    {
      const double t = 1. - (travelled - every) / length;  // where along a-b the mark falls
      draw_chevron(canvas, a + t * (b - a), (1. / length) * (b - a), size, {20, 60, 70});
    }
  }
}

// A disc in the index colour at a singularity, where it is seen.
inline void draw_singularity(const V3& c, int k, const View& view, Canvas& canvas)
{
  const int x = static_cast<int>(c[0]), y = static_cast<int>(c[1]);
  if(x < view.x0 || y < view.y0 || x >= view.x0 + view.size || y >= view.y0 + view.size) return;
  if(c[2] + 2. < canvas.depth[static_cast<std::size_t>(y * canvas.w + x)]) return;
  canvas.disc(c, 5., index_colour(k));
}

inline std::array<unsigned char, 3> feature_colour() { return {235, 140, 0}; }

// One panel: the surface, the field (lines or glyphs), the feature edges, the singular faces
// (or vertices) marked by discs so that they are seen even when smaller than a pixel.
inline void draw_view(const Scene& s, const View& view, double mean_edge, const Anchors& anchors, Canvas& canvas)
{
  std::vector<V3> screen(s.points.size());
  for(std::size_t i = 0; i < s.points.size(); ++i) screen[i] = view.project(s.points[i]);
  draw_surface(s, view, screen, canvas);
  for(const auto& polyline : s.polylines)
  {
    for(std::size_t i = 0; i + 1 < polyline.size(); ++i)
      canvas.line(view.project(polyline[i]), view.project(polyline[i + 1]), {20, 60, 70}, 3.);
    if(s.degree % 2 == 1) draw_arrowheads(polyline, view, canvas);
  }
  if(s.polylines.empty()) draw_glyphs(s, view, anchors, mean_edge, canvas);
  for(const auto& e : s.feature_edges)  // two pixels wide, so that they stand out of the field's lines
    for(const V3& shift : {V3{0., 0., 0.}, V3{1., 0., 0.}, V3{0., 1., 0.}})
      canvas.line(screen[e[0]] + shift, screen[e[1]] + shift, feature_colour(), 3.);
  for(std::size_t f = 0; f < s.triangles.size() && f < s.face_index.size(); ++f)
  {
    if(s.face_index[f] == 0) continue;
    const auto& t = s.triangles[f];
    draw_singularity((1. / 3.) * (screen[t[0]] + screen[t[1]] + screen[t[2]]), s.face_index[f], view, canvas);
  }
  for(std::size_t v = 0; v < screen.size() && v < s.vertex_index.size(); ++v)
    if(s.vertex_index[v] != 0) draw_singularity(screen[v], s.vertex_index[v], view, canvas);
}

// The index k/n as a reduced fraction with its sign: +1, -1, +1/2, -1/4.
inline std::string index_label(int k, int n)
{
  const int divisor = std::gcd(k, n);
  const int numerator = k / divisor, denominator = n / divisor;
  return (numerator > 0 ? "+" : "") + std::to_string(numerator) +
         (denominator == 1 ? std::string() : "/" + std::to_string(denominator));
}

// The legend band: n, and each index present with its colour and count.
inline void draw_legend(const Scene& s, int y0, Canvas& canvas)
{
  const std::array<unsigned char, 3> ink = {30, 30, 30};
  text(canvas, 20, y0 + 18, "n = " + std::to_string(s.degree), 3, ink);
  std::map<int, std::size_t> count;
  for(int k : s.face_index)
    if(k != 0) ++count[k];
  for(int k : s.vertex_index)
    if(k != 0) ++count[k];
  int x = 220;
  text(canvas, x, y0 + 18, count.empty() ? "no singularity" : "index:", 3, ink);
  x += (count.empty() ? 15 : 7) * 18;
  for(auto it = count.rbegin(); it != count.rend() && x < canvas.w - 200; ++it)
  {
    canvas.disc(V3{x + 10., y0 + 28., 0.}, 10., index_colour(it->first));
    const std::string label = index_label(it->first, s.degree) + " x" + std::to_string(it->second);
    text(canvas, x + 28, y0 + 18, label, 3, ink);
    x += 28 + 18 * static_cast<int>(label.size()) + 30;
  }
  if(!s.feature_edges.empty() && x < canvas.w - 200)  // after the indices, where there is room
  {
    canvas.disc(V3{x + 10., y0 + 28., 0.}, 10., feature_colour());
    text(canvas, x + 28, y0 + 18, "features", 3, ink);
  }
}

// The points' principal axes, longest first (unit vectors), and their spreads.
inline std::pair<std::array<V3, 3>, std::array<double, 3> > principal_axes(const std::vector<V3>& points)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for(const V3& p : points) mean += Eigen::Vector3d(p[0], p[1], p[2]) / static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(const V3& p : points)
  {
    const Eigen::Vector3d q = Eigen::Vector3d(p[0], p[1], p[2]) - mean;
    covariance += q * q.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);  // ascending eigenvalues
  std::array<V3, 3> axes;
  std::array<double, 3> spreads;
  for(int k = 0; k < 3; ++k)
  {
    const Eigen::Vector3d a = eigen.eigenvectors().col(2 - k);
    axes[static_cast<std::size_t>(k)] = V3{a[0], a[1], a[2]};
    spreads[static_cast<std::size_t>(k)] = std::sqrt((std::max)(0., eigen.eigenvalues()[2 - k]));
  }
  return {axes, spreads};
}

struct View_set
{
  std::array<V3, 4> directions;
  V3 up;
};

// Four directions to look from. In general the vertices of a tetrahedron, the
// first one a three-quarter view, with the file's y axis up: every face turned
// to the outside is seen from less than 71 degrees in one of them. A sheet (its
// least spread below a fifth of the next one) would be seen at a graze from
// all four: it is seen from both sides instead, straight and tilted by 50
// degrees about its longest axis, which is shown upwards (along the panel's
// diagonal if the sheet is a strip, so that it fills more of the panel).
inline View_set view_directions(const std::vector<V3>& points)
{
  const auto [axes, spreads] = principal_axes(points);
  if(spreads[2] < 0.2 * spreads[1])
  {
    const V3 &e1 = axes[0], &e2 = axes[1], &e3 = axes[2];
    const double c = std::cos(0.87), t = std::sin(0.87);  // 50 degrees
    const V3 up = spreads[1] < 0.5 * spreads[0] ? unit(e1 + e2) : e1;
    return {{unit(e3 + 0.15 * e2), unit(-1. * e3 - 0.15 * e2), c * e3 - t * e2, -c * e3 + t * e2}, up};
  }
  const V3 front = unit(V3{0.55, 0.35, 0.76}), a = unit(V3{1, 1, 1});
  const V3 axis = cross(a, front);
  const double sin_angle = norm(axis), cos_angle = dot(a, front);
  auto rotate = [&](const V3& v) {  // Rodrigues: the rotation taking a to front
    if(sin_angle < 1e-12) return v;
    const V3 k = (1. / sin_angle) * axis;
    return cos_angle * v + sin_angle * cross(k, v) + ((1. - cos_angle) * dot(k, v)) * k;
  };
  return {{front, rotate(unit(V3{1, -1, -1})), rotate(unit(V3{-1, 1, -1})), rotate(unit(V3{-1, -1, 1}))},
          V3{0, 1, 0}};
}

// Renders the scene from four directions (view_directions()), a legend below.
// Writes a PNG.
inline bool render(const Scene& s, std::ostream& os, int panel = 560)
{
  if(s.points.empty() || s.triangles.empty()) return false;
  const View_set views = view_directions(s.points);
  Anchors anchors;
  if(!s.directions_on_faces) anchors.points = s.points;
  anchors.normals.assign(anchors.points.size(), V3{0, 0, 0});
  double edge_sum = 0.;
  for(const auto& t : s.triangles)
  {
    const V3 n = cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]]);
    if(s.directions_on_faces)
    {
      anchors.points.push_back((1. / 3.) * (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]));
      anchors.normals.push_back(n);
    }
    else
      for(int c = 0; c < 3; ++c) anchors.normals[t[c]] = anchors.normals[t[c]] + n;
    for(int c = 0; c < 3; ++c) edge_sum += norm(s.points[t[(c + 1) % 3]] - s.points[t[c]]);
  }
  const double mean_edge = edge_sum / (3. * s.triangles.size());
  const int legend = 70;
  Canvas canvas(2 * panel, 2 * panel + legend);
  for(int v = 0; v < 4; ++v)
  {
    const View view = make_view(s.points, views.directions[v], views.up, (v % 2) * panel, (v / 2) * panel, panel);
    draw_view(s, view, mean_edge, anchors, canvas);
  }
  for(int x = 0; x < 2 * panel; ++x) canvas.set(x, panel, {170, 170, 170});  // the panels' borders
  for(int y = 0; y < 2 * panel; ++y) canvas.set(panel, y, {170, 170, 170});
  draw_legend(s, 2 * panel, canvas);
  return write_png(os, canvas.w, canvas.h, canvas.rgb);
}

} // namespace png_snapshot

#endif
