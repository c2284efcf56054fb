// Reading OFF, OBJ, PLY and STL files, ASCII and binary, into a polygon soup:
// the points and the polygons as the file lists them, nothing repaired.
//
// Two demands shape this reader. Speed: the whole file is read at once and
// its numbers parsed with std::from_chars, so that reading costs little beside
// the computation. Distrust: a count in a file (vertices, faces, list sizes)
// is checked against the bytes left in the file before anything is allocated
// for it, so a corrupted header costs an error message, never gigabytes; every
// error is a Mesh_input_error naming the file and the line (or byte) at fault.
//
// What is read, per format (anything else in the file is skipped):
//   OFF  ASCII ([ST][C][N]OFF: the extra values of a line are skipped) and
//        binary "OFF BINARY" (big-endian, as Geomview and CGAL write it);
//   OBJ  "v x y z" and "f i j k ..." (1-based, negative = relative, "i/t/n");
//   PLY  ascii, binary_little_endian and binary_big_endian: element vertex
//        (x, y, z of any scalar type), element face (list vertex_indices or
//        vertex_index); other elements and properties are skipped;
//   STL  ASCII and binary; identical points are shared, numbered in the order
//        of their first appearance (as CGAL's STL reader does).
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_READ_POLYGON_SOUP_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_READ_POLYGON_SOUP_H

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>
#include <unordered_map>
#include <vector>

struct Mesh_input_error : std::runtime_error { using std::runtime_error::runtime_error; };

// The polygons in one array: polygon p has the corners
// corners[first_corner[p]] ... corners[first_corner[p + 1] - 1].
struct Polygon_soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::size_t> first_corner = std::vector<std::size_t>(1, 0);
  std::vector<std::size_t> corners;

  std::size_t number_of_polygons() const { return first_corner.size() - 1; }
  std::size_t size(std::size_t p) const { return first_corner[p + 1] - first_corner[p]; }
  const std::size_t* begin(std::size_t p) const { return corners.data() + first_corner[p]; }
  const std::size_t* end(std::size_t p) const { return corners.data() + first_corner[p + 1]; }
  void end_polygon() { first_corner.push_back(corners.size()); }
};

namespace soup_reading {

inline std::string lower_case(std::string word)
{
  std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return word;
}

inline std::string lower_case_extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lower_case(path.substr(dot + 1));
}

// A piece of the file quoted in a message: at most `longest` characters,
// each non-printable one (escape codes, bytes of other encodings) shown as
// '?', so that no file can flood or drive the terminal through an error.
inline std::string excerpt(const std::string& text, std::size_t longest = 40)
{
  std::string shown;
  for(std::size_t i = 0; i < text.size() && i < longest; ++i)
    shown += std::isprint(static_cast<unsigned char>(text[i])) ? text[i] : '?';
  if(text.size() > longest) shown += "...";
  return shown;
}

// The most a pipe is read for (a regular file is read at its size).
constexpr std::size_t largest_piped_file = std::size_t(1) << 32;

// How long a named pipe may stay without a writer before it is refused.
constexpr int pipe_wait_seconds = 30;

// Why `path` could not be opened, from errno as the failing call left it
// ("cannot open 'x.off': No such file or directory").
inline std::string cannot_open(const std::string& path)
{
  if(path.empty()) return "cannot open '': the file name is empty";
  const int error = errno;
  return "cannot open '" + path + "'" + (error != 0 ? std::string(": ") + std::strerror(error) : std::string());
}

// Opens the pipe `path` without blocking, then waits for its writer (at most
// pipe_wait_seconds): a pipe nobody writes is an error, not a hang.
inline int open_pipe(const std::string& path, const std::string& what)
{
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if(fd < 0) throw Mesh_input_error(cannot_open(path));
  pollfd ready{fd, POLLIN, 0};
  int polled;
  do polled = ::poll(&ready, 1, 1000 * pipe_wait_seconds);
  while(polled < 0 && errno == EINTR);
  if(polled <= 0)
  {
    ::close(fd);
    throw Mesh_input_error("'" + path + "' is a pipe that nobody wrote to within " +
                           std::to_string(pipe_wait_seconds) + " s (" + what + " expected)");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return fd;
}

inline std::string read_pipe(const std::string& path, const std::string& what)
{
  const int fd = open_pipe(path, what);
  std::string bytes;
  char chunk[1 << 16];
  for(;;)
  {
    const ssize_t got = ::read(fd, chunk, sizeof chunk);
    if(got < 0 && errno == EINTR) continue;
    if(got <= 0)
    {
      ::close(fd);
      if(got < 0) throw Mesh_input_error("cannot read '" + path + "'");
      return bytes;
    }
    bytes.append(chunk, static_cast<std::size_t>(got));
    if(bytes.size() > largest_piped_file)
    {
      ::close(fd);
      throw Mesh_input_error("'" + path + "' is a pipe of more than " + std::to_string(largest_piped_file) + " bytes");
    }
  }
}

// The bytes of the input file `path` (`what` names it in messages: "a mesh
// file", "a prescription file"). A regular file is read in one piece; a
// named pipe until its end, up to largest_piped_file, once a writer comes
// (see open_pipe()); folders, devices (/dev/zero, /dev/urandom: no end) and
// sockets are refused.
inline std::string read_whole_file(const std::string& path, const std::string& what = "a mesh file")
{
  struct stat status;
  if(path.empty() || ::stat(path.c_str(), &status) != 0) throw Mesh_input_error(cannot_open(path));
  if(S_ISDIR(status.st_mode)) throw Mesh_input_error("'" + path + "' is a directory, not " + what);
  if(!S_ISREG(status.st_mode) && !S_ISFIFO(status.st_mode))
    throw Mesh_input_error("'" + path + "' is a device or a socket, not " + what);
  if(S_ISFIFO(status.st_mode)) return read_pipe(path, what);
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Mesh_input_error(cannot_open(path));
  std::string bytes(static_cast<std::size_t>(status.st_size), '\0');
  in.read(&bytes[0], static_cast<std::streamsize>(bytes.size()));
  if(in.gcount() != static_cast<std::streamsize>(bytes.size())) throw Mesh_input_error("cannot read '" + path + "'");
  return bytes;
}

// A cursor on a text file, line by line; comments start with '#'.
class Text_reader
{
public:
  Text_reader(const std::string& bytes, const std::string& path, std::size_t offset = 0)
    : p_(bytes.data() + offset), end_(bytes.data() + bytes.size()), path_(path)
  {}

  [[noreturn]] void fail(const std::string& message) const
  {
    throw Mesh_input_error("'" + path_ + "' line " + std::to_string(line_) + ": " + message);
  }
  std::size_t bytes_left() const { return static_cast<std::size_t>(end_ - p_); }
  const char* position() const { return p_; }
  bool at_end() const { return p_ == end_; }

  void skip_spaces()
  {
    while(p_ != end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\f' || *p_ == '\v')) ++p_;
  }
  bool at_line_end()
  {
    skip_spaces();
    return p_ == end_ || *p_ == '\n' || *p_ == '#';
  }
  void next_line()
  {
    const void* newline = std::memchr(p_, '\n', bytes_left());
    p_ = newline ? static_cast<const char*>(newline) + 1 : end_;
    ++line_;
  }
  // Moves to the next line that holds data (not blank, not a comment).
  bool next_data()
  {
    while(p_ != end_ && at_line_end())
      if(p_ != end_) next_line();
    return p_ != end_;
  }
  // Like next_data(), but across lines inside a statement (PLY ASCII, STL).
  void skip_white()
  {
    while(p_ != end_ && std::isspace(static_cast<unsigned char>(*p_)))
      if(*p_++ == '\n') ++line_;
  }
  std::string word()
  {
    skip_spaces();
    const char* start = p_;
    while(p_ != end_ && !std::isspace(static_cast<unsigned char>(*p_))) ++p_;
    return std::string(start, p_);
  }
  std::string peek_word()
  {
    const char* start = p_;
    std::string w = word();
    p_ = start;
    return w;
  }
  template <typename T>
  T number(const char* what)
  {
    skip_spaces();
    if(p_ != end_ && *p_ == '+')  // a plus sign, alone: "+-1" is no number
    {
      ++p_;
      if(p_ != end_ && (*p_ == '+' || *p_ == '-')) fail(std::string("expected ") + what + ", found '" + excerpt(word()) + "'");
    }
    T value{};
    const std::from_chars_result r = std::from_chars(p_, end_, value);
    if(r.ec == std::errc::result_out_of_range) fail(std::string(what) + " out of range");
    if(r.ec != std::errc() || (r.ptr != end_ && !std::isspace(static_cast<unsigned char>(*r.ptr)) && *r.ptr != '/' &&
                               *r.ptr != '#'))
      fail(std::string("expected ") + what + ", found '" + excerpt(word()) + "'");
    p_ = r.ptr;
    return value;
  }
  // Skips the rest of a token (the "/t/n" of an OBJ corner).
  void skip_token() { while(p_ != end_ && !std::isspace(static_cast<unsigned char>(*p_))) ++p_; }

private:
  const char* p_;
  const char* end_;
  std::string path_;
  std::size_t line_ = 1;
};

// A cursor on binary data of either byte order.
class Binary_reader
{
public:
  Binary_reader(const std::string& bytes, const std::string& path, std::size_t offset, bool big_endian)
    : begin_(bytes.data()), p_(bytes.data() + offset), end_(bytes.data() + bytes.size()), path_(path),
      big_endian_(big_endian)
  {}

  [[noreturn]] void fail(const std::string& message) const
  {
    throw Mesh_input_error("'" + path_ + "' byte " + std::to_string(p_ - begin_) + ": " + message);
  }
  std::size_t bytes_left() const { return static_cast<std::size_t>(end_ - p_); }
  void skip(std::size_t n, const char* what)
  {
    if(n > bytes_left()) fail(std::string("the file ends inside ") + what);
    p_ += n;
  }
  template <typename T>
  T get(const char* what)
  {
    if(sizeof(T) > bytes_left()) fail(std::string("the file ends inside ") + what);
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, p_, sizeof(T));
    if(big_endian_ != host_is_big_endian()) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    p_ += sizeof(T);
    return value;
  }

private:
  static bool host_is_big_endian()
  {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 0;
  }
  const char* begin_;
  const char* p_;
  const char* end_;
  std::string path_;
  bool big_endian_;
};

// `count` items of at least `bytes_each` bytes cannot be in `bytes_left` bytes.
template <typename Reader>
void check_count(const Reader& r, long long count, std::size_t bytes_each, const std::string& what)
{
  if(count < 0) r.fail("negative number of " + what);
  if(bytes_each > 0 && static_cast<unsigned long long>(count) > r.bytes_left() / bytes_each)
    r.fail("the header announces " + std::to_string(count) + " " + what + ", more than the " +
           std::to_string(r.bytes_left()) + " bytes left in the file can hold");
}

// Text as the readers expect it: a leading UTF-8 byte-order mark removed,
// and (`line_ends`) the lone carriage returns of a file that has no line
// feed (old Mac line ends) turned into line feeds. CR LF needs nothing: a
// carriage return counts as a space.
inline void prepare_text(std::string& bytes, bool line_ends)
{
  if(bytes.compare(0, 3, "\xEF\xBB\xBF") == 0) bytes.erase(0, 3);
  if(line_ends && bytes.find('\n') == std::string::npos) std::replace(bytes.begin(), bytes.end(), '\r', '\n');
}

inline std::array<double, 3> finite_point(double x, double y, double z, const char* format, std::size_t index)
{
  if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    throw Mesh_input_error(std::string(format) + " vertex " + std::to_string(index) + " has a non-finite coordinate");
  return {x, y, z};
}

} // namespace soup_reading

#include "read_polygon_soup_formats.h"

// Reads `path` (by its extension: .off, .obj, .ply or .stl, any case) into a
// polygon soup. Throws Mesh_input_error with a one-line message if the file
// cannot be read, is malformed, or refers to a vertex it does not have.
inline Polygon_soup read_polygon_soup(const std::string& path)
{
  namespace sr = soup_reading;
  struct stat status;
  if(path.empty() || ::stat(path.c_str(), &status) != 0) throw Mesh_input_error(sr::cannot_open(path));
  if(S_ISDIR(status.st_mode)) throw Mesh_input_error("'" + path + "' is a directory, not a mesh file");
  const std::string extension = sr::lower_case_extension(path);
  if(extension != "off" && extension != "obj" && extension != "ply" && extension != "stl")
    throw Mesh_input_error("'" + path + "': unknown mesh format (the name must end in .off, .obj, .ply or .stl)");
  std::string bytes = sr::read_whole_file(path);
  if(extension != "stl") sr::prepare_text(bytes, extension != "ply");  // STL: once it is known to be ASCII
  Polygon_soup soup;
  if(extension == "off") sr::read_OFF(bytes, path, soup);
  else if(extension == "obj") sr::read_OBJ(bytes, path, soup);
  else if(extension == "ply") sr::read_PLY(bytes, path, soup);
  else sr::read_STL(bytes, path, soup);
  for(std::size_t c = 0; c < soup.corners.size(); ++c)
    if(soup.corners[c] >= soup.points.size())
    {
      const std::size_t face = static_cast<std::size_t>(
        std::upper_bound(soup.first_corner.begin(), soup.first_corner.end(), c) - soup.first_corner.begin() - 1);
      throw Mesh_input_error("face " + std::to_string(face) + " refers to vertex " + std::to_string(soup.corners[c]) +
                             ", which does not exist");
    }
  return soup;
}

#endif
