// The files a run of direction_field writes, made safe for the user:
//  - every output path is tried before the mesh is read (a temporary file is
//    created beside it), so that a typo fails at once, not after the computation;
//  - each output is written under its temporary name and checked after its last
//    write and close (a full disk is an error, not a short file);
//  - the temporary files are renamed to their names only when every output of
//    the run has been written; on any failure no file of this run remains.
// A path that exists and is not a regular file (/dev/null, /dev/stdout, a
// pipe) is written directly, and checked the same way. A run stopped by a
// signal whose default action ends the program (INT, TERM, HUP, QUIT, XFSZ,
// XCPU, ALRM, USR1, USR2, VTALRM), or a call of exit() inside a library,
// removes its temporary files before it ends
// (the program ignores PIPE: a closed standard output is a write error).
// A path that is a symbolic link is written through it: the link stays and
// its target gets the new content. No output may be one of the run's input
// files, whatever its spelling (compared by device and inode).
// Two outputs are one file when their folders resolve to the same one and
// their names match, or when they are the same existing file (links). If a
// rename fails while the outputs are put in place, those already renamed are
// taken back and the older files of those names restored.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_OUTPUT_FILES_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_OUTPUT_FILES_H

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

// The temporary files of the run, where a signal handler can reach them
// (fixed storage: the handler may only call async-signal-safe functions).
namespace output_files_internal {

constexpr int most_files = 32;
constexpr std::size_t longest_path = 4096;
inline char temporary_paths[most_files][longest_path];
inline volatile std::sig_atomic_t temporary_count = 0;

extern "C" inline void remove_temporaries_and_stop(int signal)
{
  for(int i = 0; i < temporary_count; ++i)
    if(temporary_paths[i][0] != '\0') ::unlink(temporary_paths[i]);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// A library that ends the process with exit() (libgomp when it cannot create
// a thread, for one) leaves no temporary file either.
extern "C" inline void remove_temporaries_at_exit()
{
  for(int i = 0; i < temporary_count; ++i)
    if(temporary_paths[i][0] != '\0') ::unlink(temporary_paths[i]);
}

// Records `path` (returns its slot, or -1 if it cannot be recorded).
inline int remember(const std::string& path)
{
  if(temporary_count >= most_files || path.size() >= longest_path) return -1;
  const int slot = temporary_count;
  std::memcpy(temporary_paths[slot], path.c_str(), path.size() + 1);
  temporary_count = slot + 1;
  if(slot == 0) std::atexit(remove_temporaries_at_exit);
  if(slot == 0)
    for(int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGXFSZ, SIGXCPU, SIGALRM, SIGUSR1, SIGUSR2, SIGVTALRM})
      std::signal(s, remove_temporaries_and_stop);
  return slot;
}

inline void forget(int slot)
{
  if(slot >= 0) temporary_paths[slot][0] = '\0';
}

} // namespace output_files_internal

// An output that cannot be written, or that would replace an input.
struct Output_error : std::runtime_error { using std::runtime_error::runtime_error; };

// The files the run reads, by what names them ("--prescribe") and path.
typedef std::vector<std::pair<std::string, std::string> > Input_files;

class Output_files
{
public:
  // `remove_on_signal`: a signal that ends the process removes the temporary
  // files (the program); false leaves the process's signal handlers alone
  // (the Python module, whose interpreter owns them).
  explicit Output_files(bool remove_on_signal = true) : remove_on_signal_(remove_on_signal) {}
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  ~Output_files() { discard(); }

  // Registers the output `path` of `option` (nothing if `path` is empty);
  // no input file may be replaced by it.
  void add(const std::string& option, const std::string& path, const Input_files& inputs)
  {
    if(path.empty()) return;
    if(path == "-") throw Output_error(option + " needs a file name (use /dev/stdout to write to standard output)");
    if(path.find('\0') != std::string::npos) throw Output_error(option + ": the file name contains a NUL character");
    const std::string target = link_target(path);
    struct stat existing;
    const bool exists = ::stat(target.c_str(), &existing) == 0;
    if(exists && S_ISDIR(existing.st_mode)) throw Output_error(option + " '" + path + "' is a directory");
    if(exists) refuse_inputs(option, path, existing, inputs);
    const std::string key = resolved(target);
    for(const auto& f : files_)
      if(f->path == path || f->key == key ||
         (exists && f->exists && f->device == existing.st_dev && f->inode == existing.st_ino))
        throw Output_error(f->option + " and " + option + " both write '" + path + "'");
    const bool direct = exists && !S_ISREG(existing.st_mode);  // a device or a pipe: written as it is
    std::unique_ptr<File> f(new File{option, path, target, direct ? target : temporary_name(target), {}});
    f->key = key;
    f->exists = exists;
    f->device = exists ? existing.st_dev : 0;
    f->inode = exists ? existing.st_ino : 0;
    if(f->written != f->target && remove_on_signal_) f->slot = output_files_internal::remember(f->written);
    f->stream.open(f->written, std::ios::binary | std::ios::trunc);
    if(!f->stream) throw Output_error("cannot write " + option + " '" + path + "': " + std::strerror(errno));
    files_.push_back(std::move(f));
  }

  // The stream of the output `path` (registered by add()).
  std::ostream& stream(const std::string& path) { return find(path).stream; }

  // Flushes and closes the output `path`; throws if anything written to it was lost.
  void close(const std::string& path)
  {
    File& f = find(path);
    f.stream.flush();
    const bool written = static_cast<bool>(f.stream);
    f.stream.close();
    if(!written || !f.stream) throw Output_error("could not write " + f.option + " '" + f.path + "' (disk full?)");
  }

  // Writes nothing for the output `path` after all (a dataset meshio could
  // not read back): its temporary file goes, and at commit() an older
  // regular file of that name goes too, so that no stale result stays under
  // the name (a device or a pipe is simply not written to).
  void leave_out(const std::string& path)
  {
    File& f = find(path);
    f.stream.close();
    if(f.written != f.target) std::remove(f.written.c_str());
    f.left_out = true;
  }

  // The options whose outputs were left out, with their paths.
  std::vector<std::pair<std::string, std::string> > left_out() const
  {
    std::vector<std::pair<std::string, std::string> > list;
    for(const auto& f : files_)
      if(f->left_out) list.emplace_back(f->option, f->path);
    return list;
  }

  // Closes every output but `path`, checked.
  void close_all_except(const std::string& path)
  {
    for(auto& f : files_)
      if(f->path != path && f->stream.is_open()) close(f->path);
  }

  // Gives every output its name; call once everything has been written.
  // An older file of that name is kept under a second link until all are in
  // place, so that a failure can restore it.
  void commit()
  {
    for(auto& f : files_)
      if(f->stream.is_open()) close(f->path);
    for(auto& f : files_)
      if(f->written != f->target) keep_older(*f);
    for(std::size_t i = 0; i < files_.size(); ++i)
    {
      File& f = *files_[i];
      if(f.left_out)
      {
        f.committed = f.written != f.target && !f.older.empty() && ::unlink(f.target.c_str()) == 0;
        output_files_internal::forget(f.slot);
        continue;
      }
      if(f.written != f.target && std::rename(f.written.c_str(), f.target.c_str()) != 0)
      {
        const std::string reason = std::strerror(errno);
        for(std::size_t j = 0; j < i; ++j) take_back(*files_[j]);
        for(auto& g : files_) drop_older(*g);
        throw Output_error("cannot write " + f.option + " '" + f.path + "': " + reason);
      }
      f.committed = true;
      output_files_internal::forget(f.slot);
    }
    for(auto& f : files_) drop_older(*f);
  }

private:
  struct File
  {
    std::string option, path, target;  // target: the path, or the file its link names
    std::string written;               // the temporary name, or the target itself
    std::ofstream stream;
    bool committed = false;
    int slot = -1;  // in output_files_internal's list of temporary files
    std::string key;        // the path with its folder resolved
    bool exists = false;    // the path named an existing file when added
    dev_t device = 0;
    ino_t inode = 0;
    std::string older;      // during commit(): a second link to the older file of that name
    bool left_out = false;  // leave_out(): nothing written under this name
  };

  // The file a symbolic link names (the path itself if it is no link, or if
  // the link leads nowhere).
  static std::string link_target(const std::string& path)
  {
    struct stat link;
    if(::lstat(path.c_str(), &link) != 0 || !S_ISLNK(link.st_mode)) return path;
    char* real = ::realpath(path.c_str(), nullptr);
    if(!real) return path;
    const std::string target = real;
    std::free(real);
    return target;
  }

  // Refuses an output that is one of the inputs (an existing file `existing`).
  static void refuse_inputs(const std::string& option, const std::string& path, const struct stat& existing,
                            const Input_files& inputs)
  {
    for(const auto& input : inputs)
    {
      struct stat read;
      if(input.second.empty() || ::stat(input.second.c_str(), &read) != 0) continue;
      if(read.st_dev == existing.st_dev && read.st_ino == existing.st_ino)
        throw Output_error(option + " '" + path + "' is the " + input.first + " file, which is never overwritten");
    }
  }

  // The path with its folder resolved (links, "..", "."): one key per file.
  static std::string resolved(const std::string& path)
  {
    const std::size_t slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    char* real = ::realpath(folder.c_str(), nullptr);
    if(!real) return path;
    const std::string key = std::string(real) + "/" + name;
    std::free(real);
    return key;
  }

  void keep_older(File& f)
  {
    struct stat existing;
    if(::lstat(f.target.c_str(), &existing) != 0 || !S_ISREG(existing.st_mode)) return;
    std::string name = f.written + ".older";
    if(::link(f.target.c_str(), name.c_str()) == 0) f.older = name;
  }

  // Undoes the rename of f: its older file back, or no file of that name.
  void take_back(File& f)
  {
    if(f.written == f.target || !f.committed) return;
    if(!f.older.empty() && std::rename(f.older.c_str(), f.target.c_str()) == 0) f.older.clear();
    else if(f.left_out) {}  // its older file could not be put back: nothing else to undo
    else if(f.older.empty()) std::remove(f.target.c_str());
    f.committed = false;
  }

  void drop_older(File& f)
  {
    if(!f.older.empty()) ::unlink(f.older.c_str());
    f.older.clear();
  }

  File& find(const std::string& path)
  {
    for(auto& f : files_)
      if(f->path == path) return *f;
    throw std::logic_error("output '" + path + "' was not registered");
  }

  // A new file beside `path`, readable as a file created by the user would be.
  static std::string temporary_name(const std::string& path)
  {
    const std::size_t slash = path.find_last_of('/');
    const std::string directory = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    std::string pattern = directory + "." + name + ".partial-XXXXXX";
    const int fd = ::mkstemp(&pattern[0]);
    if(fd < 0) throw Output_error("cannot write '" + path + "': " + std::strerror(errno));
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    ::close(fd);
    return pattern;
  }

  void discard()
  {
    for(auto& f : files_)
    {
      if(f->stream.is_open()) f->stream.close();
      if(!f->committed && f->written != f->target) std::remove(f->written.c_str());
      output_files_internal::forget(f->slot);
    }
  }

  bool remove_on_signal_;
  std::vector<std::unique_ptr<File> > files_;
};

#endif
