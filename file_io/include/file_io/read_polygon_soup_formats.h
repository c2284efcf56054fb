// The four formats of read_polygon_soup.h, one reader each; included from there.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_READ_POLYGON_SOUP_FORMATS_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_READ_POLYGON_SOUP_FORMATS_H

namespace soup_reading {

// ---------------------------------------------------------------- OFF

// Binary OFF (after the "OFF BINARY" line): big-endian int32 counts, float32
// coordinates, faces as int32 size, int32 indices, int32 number of colour
// values and those values.
inline void read_OFF_binary(const std::string& bytes, const std::string& path, std::size_t offset, Polygon_soup& soup)
{
  Binary_reader r(bytes, path, offset, true);
  const long long nv = r.get<std::int32_t>("the header"), nf = r.get<std::int32_t>("the header");
  r.get<std::int32_t>("the header");
  check_count(r, nv, 12, "vertices");
  soup.points.reserve(static_cast<std::size_t>(nv));
  for(long long v = 0; v < nv; ++v)
  {
    const double x = r.get<float>("a vertex"), y = r.get<float>("a vertex"), z = r.get<float>("a vertex");
    soup.points.push_back(finite_point(x, y, z, "OFF", static_cast<std::size_t>(v)));
  }
  check_count(r, nf, 8, "faces");
  soup.first_corner.reserve(static_cast<std::size_t>(nf) + 1);
  for(long long f = 0; f < nf; ++f)
  {
    const long long k = r.get<std::int32_t>("a face");
    check_count(r, k, 4, "vertices in face " + std::to_string(f));
    for(long long i = 0; i < k; ++i)
    {
      const std::int32_t index = r.get<std::int32_t>("a face");
      if(index < 0) r.fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(index));
      soup.corners.push_back(static_cast<std::size_t>(index));
    }
    soup.end_polygon();
    const long long colours = r.get<std::int32_t>("a face");
    if(colours < 0 || colours > 4) r.fail("face " + std::to_string(f) + " has " + std::to_string(colours) + " colour values");
    r.skip(4 * static_cast<std::size_t>(colours), "a face");
  }
}

// The vertices and faces of an ASCII OFF file, one per line (the values after
// the coordinates or after a face's indices, colours and the like, are skipped).
inline void read_OFF_text_body(Text_reader& r, long long nv, long long nf, Polygon_soup& soup)
{
  check_count(r, nv, 6, "vertices");  // "0 0 0\n"
  soup.points.reserve(static_cast<std::size_t>(nv));
  for(long long v = 0; v < nv; ++v)
  {
    if(!r.next_data()) r.fail("the file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    const double x = r.number<double>("a coordinate"), y = r.number<double>("a coordinate"),
                 z = r.number<double>("a coordinate");
    soup.points.push_back(finite_point(x, y, z, "OFF", static_cast<std::size_t>(v)));
    r.next_line();
  }
  check_count(r, nf, 2, "faces");  // "0\n"
  soup.first_corner.reserve(static_cast<std::size_t>(nf) + 1);
  for(long long f = 0; f < nf; ++f)
  {
    if(!r.next_data()) r.fail("the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const long long k = r.number<long long>("the number of vertices of a face");
    check_count(r, k, 2, "vertices in face " + std::to_string(f));
    for(long long i = 0; i < k; ++i)
    {
      if(r.at_line_end())
        r.fail("face " + std::to_string(f) + " announces " + std::to_string(k) + " vertices and lists " + std::to_string(i));
      const long long index = r.number<long long>("a vertex index");
      if(index < 0) r.fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(index));
      soup.corners.push_back(static_cast<std::size_t>(index));
    }
    soup.end_polygon();
    r.next_line();
  }
}

// The keyword: [ST][C][N]OFF, then BINARY or the counts.
inline void read_OFF(const std::string& bytes, const std::string& path, Polygon_soup& soup)
{
  Text_reader r(bytes, path);
  if(!r.next_data()) r.fail("empty file");
  const std::string keyword = r.word();
  const std::size_t off = keyword.rfind("OFF");
  if(off == std::string::npos || off + 3 != keyword.size()) r.fail("not an OFF file (first word '" + excerpt(keyword) + "')");
  const std::string prefix = keyword.substr(0, off);
  if(prefix.find('4') != std::string::npos || prefix.find('n') != std::string::npos)
    r.fail(keyword + " (homogeneous or n-dimensional points) is not supported");
  if(prefix.find_first_not_of("STCN") != std::string::npos) r.fail("not an OFF file (first word '" + excerpt(keyword) + "')");
  if(!r.at_line_end() && r.peek_word() == "BINARY")
  {
    if(!prefix.empty()) r.fail("binary " + excerpt(keyword) + " (with normals, colours or textures) is not supported");
    r.next_line();
    read_OFF_binary(bytes, path, static_cast<std::size_t>(r.position() - bytes.data()), soup);
    return;
  }
  if(!r.next_data()) r.fail("no vertex and face counts");
  const long long nv = r.number<long long>("the number of vertices");
  if(!r.next_data()) r.fail("no face count");
  const long long nf = r.number<long long>("the number of faces");
  r.next_line();  // the number of edges, if any, is not used
  read_OFF_text_body(r, nv, nf, soup);
}

// ---------------------------------------------------------------- OBJ

// One "f" line; indices are resolved against the vertices read so far.
inline void read_OBJ_face(Text_reader& r, Polygon_soup& soup)
{
  while(!r.at_line_end())
  {
    const long long index = r.number<long long>("a vertex index");
    r.skip_token();  // "/texture/normal"
    const long long count = static_cast<long long>(soup.points.size());
    if(index == 0 || (index < 0 && index < -count)) r.fail("vertex index " + std::to_string(index) + " does not exist");
    soup.corners.push_back(static_cast<std::size_t>(index > 0 ? index - 1 : count + index));
  }
  soup.end_polygon();
}

inline void read_OBJ(const std::string& bytes, const std::string& path, Polygon_soup& soup)
{
  Text_reader r(bytes, path);
  while(r.next_data())
  {
    const std::string keyword = r.word();
    if(keyword == "v")
    {
      const double x = r.number<double>("a coordinate"), y = r.number<double>("a coordinate"),
                   z = r.number<double>("a coordinate");
      soup.points.push_back(finite_point(x, y, z, "OBJ", soup.points.size()));
    }
    else if(keyword == "f")
      read_OBJ_face(r, soup);
    r.next_line();  // any other statement is not part of the surface
  }
}

// ---------------------------------------------------------------- PLY

struct PLY_property
{
  std::string name;
  int size = 0;             // bytes of the value (of the items, for a list)
  char kind = 'f';          // 'i' signed, 'u' unsigned, 'f' floating point
  int count_size = 0;       // > 0 for a list: bytes of its length
  char count_kind = 'u';
};

struct PLY_element
{
  std::string name;
  long long count = 0;
  std::vector<PLY_property> properties;
};

struct PLY_header
{
  bool ascii = true, big_endian = false;
  std::vector<PLY_element> elements;
  std::size_t data_offset = 0;
};

inline bool PLY_type(const std::string& name, int& size, char& kind)
{
  static const struct { const char* name; int size; char kind; } types[] = {
    {"char", 1, 'i'},  {"int8", 1, 'i'},    {"uchar", 1, 'u'},  {"uint8", 1, 'u'},   {"short", 2, 'i'},
    {"int16", 2, 'i'}, {"ushort", 2, 'u'},  {"uint16", 2, 'u'}, {"int", 4, 'i'},     {"int32", 4, 'i'},
    {"uint", 4, 'u'},  {"uint32", 4, 'u'},  {"float", 4, 'f'},  {"float32", 4, 'f'}, {"double", 8, 'f'},
    {"float64", 8, 'f'}};
  for(const auto& t : types)
    if(name == t.name) { size = t.size; kind = t.kind; return true; }
  return false;
}

// One "property" line (after the word "property").
inline PLY_property read_PLY_property(Text_reader& r)
{
  PLY_property p;
  std::string type = r.word();
  if(type == "list")
  {
    if(!PLY_type(r.word(), p.count_size, p.count_kind) || p.count_kind == 'f')
      r.fail("a PLY list needs an integer length type");
    type = r.word();
  }
  if(!PLY_type(type, p.size, p.kind)) r.fail("unknown PLY type '" + excerpt(type) + "'");
  p.name = r.word();
  if(p.name.empty()) r.fail("a PLY property without a name");
  return p;
}

inline PLY_header read_PLY_header(const std::string& bytes, const std::string& path)
{
  Text_reader r(bytes, path);
  if(r.word() != "ply") r.fail("not a PLY file (no 'ply' on the first line)");
  PLY_header header;
  bool format_seen = false;
  for(r.next_line(); !r.at_end(); r.next_line())
  {
    const std::string keyword = r.word();
    if(keyword == "format")
    {
      const std::string format = r.word();
      if(format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        r.fail("unknown PLY format '" + excerpt(format) + "'");
      header.ascii = format == "ascii";
      header.big_endian = format == "binary_big_endian";
      format_seen = true;
    }
    else if(keyword == "element")
    {
      PLY_element e;
      e.name = r.word();
      e.count = r.number<long long>("an element count");
      if(e.count < 0) r.fail("negative element count");
      header.elements.push_back(e);
    }
    else if(keyword == "property")
    {
      if(header.elements.empty()) r.fail("a PLY property before any element");
      header.elements.back().properties.push_back(read_PLY_property(r));
    }
    else if(keyword == "end_header")
    {
      if(!format_seen) r.fail("a PLY header without a format line");
      r.next_line();
      header.data_offset = static_cast<std::size_t>(r.position() - bytes.data());
      return header;
    }
    else if(keyword != "comment" && keyword != "obj_info" && !keyword.empty())
      r.fail("unexpected '" + excerpt(keyword) + "' in a PLY header");
  }
  r.fail("the PLY header has no end_header");
}

// The least number of bytes an element can take: every scalar, every list's
// length (binary), or one character and a separator per value (ASCII).
inline std::size_t PLY_minimum_size(const PLY_element& e, bool ascii)
{
  std::size_t size = 0;
  for(const PLY_property& p : e.properties)
    size += ascii ? 2 : static_cast<std::size_t>(p.count_size > 0 ? p.count_size : p.size);
  return size;
}

// The values of the elements, ASCII or binary, through one interface.
class PLY_values
{
public:
  PLY_values(const std::string& bytes, const std::string& path, const PLY_header& h)
    : ascii_(h.ascii), text_(bytes, path, h.data_offset), binary_(bytes, path, h.data_offset, h.big_endian)
  {}
  double value(int size, char kind)
  {
    if(ascii_) { text_.skip_white(); return text_.number<double>("a PLY value"); }
    switch(size * 4 + (kind == 'f' ? 0 : kind == 'i' ? 1 : 2))
    {
      case 4 + 1: return binary_.get<std::int8_t>("a PLY value");
      case 4 + 2: return binary_.get<std::uint8_t>("a PLY value");
      case 8 + 1: return binary_.get<std::int16_t>("a PLY value");
      case 8 + 2: return binary_.get<std::uint16_t>("a PLY value");
      case 16 + 0: return binary_.get<float>("a PLY value");
      case 16 + 1: return binary_.get<std::int32_t>("a PLY value");
      case 16 + 2: return binary_.get<std::uint32_t>("a PLY value");
      default: return binary_.get<double>("a PLY value");
    }
  }
  // A list's length, checked against what is left.
  long long list_length(const PLY_property& p)
  {
    const double length = value(p.count_size, p.count_kind);
    if(!(length >= 0. && length == std::floor(length))) fail("invalid PLY list length");
    const std::size_t each = ascii_ ? 2 : static_cast<std::size_t>(p.size);
    if(length > static_cast<double>(bytes_left() / each))
      fail("a PLY list of " + std::to_string(static_cast<long long>(length)) + " items, more than the file holds");
    return static_cast<long long>(length);
  }
  std::size_t bytes_left() const { return ascii_ ? text_.bytes_left() : binary_.bytes_left(); }
  [[noreturn]] void fail(const std::string& message) const { ascii_ ? text_.fail(message) : binary_.fail(message); }

private:
  bool ascii_;
  Text_reader text_;
  Binary_reader binary_;
};

// One element of every kind: vertices give points, faces give polygons, the
// rest is read past.
inline void read_PLY_element(PLY_values& values, const PLY_element& e, Polygon_soup& soup)
{
  const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
  double xyz[3] = {0., 0., 0.};
  for(const PLY_property& p : e.properties)
  {
    const bool indices = is_face && (p.name == "vertex_indices" || p.name == "vertex_index");
    if(p.count_size == 0)
    {
      const double x = values.value(p.size, p.kind);
      if(is_vertex && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z') xyz[p.name[0] - 'x'] = x;
      continue;
    }
    const long long length = values.list_length(p);
    for(long long i = 0; i < length; ++i)
    {
      const double index = values.value(p.size, p.kind);
      if(!indices) continue;
      // an integer value, exactly (a float property may hold one), below 2^63
      if(!(index >= 0. && index == std::floor(index) && index < 9223372036854775808.))
        values.fail("invalid vertex index in a PLY face");
      soup.corners.push_back(static_cast<std::size_t>(index));
    }
    if(indices) soup.end_polygon();
  }
  if(is_vertex) soup.points.push_back(finite_point(xyz[0], xyz[1], xyz[2], "PLY", soup.points.size()));
}

inline void read_PLY(const std::string& bytes, const std::string& path, Polygon_soup& soup)
{
  const PLY_header header = read_PLY_header(bytes, path);
  PLY_values values(bytes, path, header);
  for(const PLY_element& e : header.elements)
  {
    const std::size_t minimum = PLY_minimum_size(e, header.ascii);
    if(minimum == 0) continue;  // nothing to read, however many
    if(static_cast<unsigned long long>(e.count) > values.bytes_left() / minimum)
      values.fail("the header announces " + std::to_string(e.count) + " " + e.name + " elements, more than the " +
                  std::to_string(values.bytes_left()) + " bytes left in the file can hold");
    if(e.name == "vertex") soup.points.reserve(static_cast<std::size_t>(e.count));
    if(e.name == "face") soup.first_corner.reserve(static_cast<std::size_t>(e.count) + 1);
    for(long long i = 0; i < e.count; ++i) read_PLY_element(values, e, soup);
  }
}

// ---------------------------------------------------------------- STL

// The shared points of an STL file, numbered by first appearance.
class STL_points
{
public:
  explicit STL_points(Polygon_soup& soup) : soup_(soup) {}
  void add(double x, double y, double z)
  {
    const std::array<double, 3> p = finite_point(x + 0., y + 0., z + 0., "STL", soup_.points.size());  // -0 is 0
    const auto inserted = index_.emplace(p, soup_.points.size());
    if(inserted.second) soup_.points.push_back(p);
    soup_.corners.push_back(inserted.first->second);
  }

private:
  struct Hash
  {
    std::size_t operator()(const std::array<double, 3>& p) const
    {
      std::size_t h = 0;
      for(double x : p)
      {
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
      }
      return h ^ (h >> 29);
    }
  };
  Polygon_soup& soup_;
  std::unordered_map<std::array<double, 3>, std::size_t, Hash> index_;
};

inline void read_STL_binary(const std::string& bytes, const std::string& path, Polygon_soup& soup)
{
  Binary_reader r(bytes, path, 80, false);
  const long long count = r.get<std::uint32_t>("the header");
  check_count(r, count, 50, "triangles");
  STL_points points(soup);
  soup.first_corner.reserve(static_cast<std::size_t>(count) + 1);
  for(long long t = 0; t < count; ++t)
  {
    r.skip(12, "a triangle");  // the normal
    for(int c = 0; c < 3; ++c)
    {
      const double x = r.get<float>("a triangle"), y = r.get<float>("a triangle"), z = r.get<float>("a triangle");
      points.add(x, y, z);
    }
    soup.end_polygon();
    r.skip(2, "a triangle");  // the attribute byte count
  }
}

// ASCII STL's keywords, in any case
inline void expect_word(Text_reader& r, const char* word)
{
  r.skip_white();
  const std::string found = r.word();
  if(lower_case(found) != word) r.fail(std::string("expected '") + word + "', found '" + excerpt(found) + "'");
}

// facet normal nx ny nz / outer loop / vertex x y z (three times) / endloop / endfacet
inline void read_STL_text(const std::string& bytes, const std::string& path, Polygon_soup& soup)
{
  Text_reader r(bytes, path);
  STL_points points(soup);
  for(r.skip_white(); !r.at_end(); r.skip_white())
  {
    const std::string keyword = lower_case(r.word());
    if(keyword == "solid" || keyword == "endsolid") { r.next_line(); continue; }  // and the solid's name
    if(keyword != "facet") r.fail("expected 'facet', found '" + excerpt(keyword) + "'");
    r.next_line();  // "normal nx ny nz"
    expect_word(r, "outer");
    expect_word(r, "loop");
    for(int c = 0; c < 3; ++c)
    {
      expect_word(r, "vertex");
      const double x = r.number<double>("a coordinate"), y = r.number<double>("a coordinate"),
                   z = r.number<double>("a coordinate");
      points.add(x, y, z);
    }
    soup.end_polygon();
    expect_word(r, "endloop");
    expect_word(r, "endfacet");
  }
}

// Whether the bytes from `first` look like text: no control character but
// white space in the first 4 KiB (a binary STL's triangles have zero bytes).
inline bool looks_like_text(const std::string& bytes, std::size_t first)
{
  for(std::size_t i = first; i < bytes.size() && i < first + 4096; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(bytes[i]);
    if(c < 32 && !std::isspace(c)) return false;
  }
  return true;
}

// Binary when the size is exactly that of a binary file (84 + 50 bytes per
// triangle, the count at byte 80), whatever its header says; otherwise ASCII
// when the text (after a byte-order mark) starts with "solid", in any case,
// and looks like text; otherwise binary (a binary file whose header starts
// with "solid" and whose size is off is read as binary: a missing byte is a
// truncated triangle, extra bytes after the last triangle are ignored).
inline void read_STL(std::string& bytes, const std::string& path, Polygon_soup& soup)
{
  const std::uint32_t count = bytes.size() >= 84 ? Binary_reader(bytes, path, 80, false).get<std::uint32_t>("") : 0;
  const bool binary_size = bytes.size() >= 84 && (bytes.size() - 84) / 50 == count && (bytes.size() - 84) % 50 == 0;
  const std::size_t text = bytes.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  const std::size_t first = bytes.find_first_not_of(" \t\r\n", text);
  const bool starts_with_solid = first != std::string::npos && lower_case(bytes.substr(first, 5)) == "solid" &&
                                 (first + 5 == bytes.size() || std::isspace(static_cast<unsigned char>(bytes[first + 5])));
  if(!binary_size && starts_with_solid && looks_like_text(bytes, text))
  {
    prepare_text(bytes, true);
    read_STL_text(bytes, path, soup);
  }
  else if(bytes.size() < 84) throw Mesh_input_error("'" + path + "' is too short for a binary STL file");
  else read_STL_binary(bytes, path, soup);
}

} // namespace soup_reading

#endif
