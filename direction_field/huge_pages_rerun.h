// The program's memory pages (--huge-pages, direction_field/README.md).
//
// Most of a large run's memory is written once, fresh from the kernel, and on
// some virtual machines a page fault is expensive (benchmark/.../README.md,
// "Huge pages for the program"); on others huge pages cost more than they
// save, so --huge-pages auto first measures. glibc (2.35 or later) gives
// transparent huge pages to every large
// allocation of a process started with GLIBC_TUNABLES=glibc.malloc.hugetlb=1,
// a setting it reads only at start: so the program runs itself again with
// it. A library must not choose its process's allocator; the program is the
// process, so it may. Results are the same bit for bit; only the time changes.
#ifndef SMDF_DIRECTION_FIELD_HUGE_PAGES_RERUN_H
#define SMDF_DIRECTION_FIELD_HUGE_PAGES_RERUN_H

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#if defined(__linux__) && defined(__GLIBC__)
#include <sys/auxv.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

constexpr const char* huge_pages_tunable = "glibc.malloc.hugetlb=1";

// Whether this process runs in glibc's secure mode (setuid or setgid, or
// with capabilities): glibc then ignores GLIBC_TUNABLES, and newer versions
// remove it, so a rerun would run again without it.
inline bool secure_mode()
{
#if defined(__linux__) && defined(__GLIBC__)
  return getauxval(AT_SECURE) != 0;
#else
  return false;
#endif
}

// Whether this process's malloc takes transparent huge pages: the last
// glibc.malloc.hugetlb of GLIBC_TUNABLES is a value glibc accepts (a
// decimal number from 0 to 2; glibc ignores any other) and is 1 or 2.
inline bool malloc_uses_huge_pages()
{
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if(tunables == nullptr || secure_mode()) return false;
  const std::string all(tunables), name = "glibc.malloc.hugetlb=";
  int value = 0;
  for(std::size_t start = 0; start <= all.size();)
  {
    std::size_t end = all.find(':', start);
    if(end == std::string::npos) end = all.size();
    const std::string entry = all.substr(start, end - start);
    if(entry.compare(0, name.size(), name) == 0)
    {
      const std::string v = entry.substr(name.size());
      if(!v.empty() && v.size() < 10 && v.find_first_not_of("0123456789") == std::string::npos &&
         std::stoi(v) <= 2)
        value = std::stoi(v);
    }
    start = end + 1;
  }
  return value != 0;
}

#if defined(__linux__) && defined(__GLIBC__)
// Whether /proc/self/exe is the file that holds this program's code: not
// where the program was started through the dynamic loader
// (ld-linux-x86-64.so.2 direction_field ...), where it names the loader.
// The kernel names both files alike: the executable's link, and the mapping
// of this function's code in /proc/self/maps.
inline bool executable_is_this_program()
{
  char link[4096];
  const ssize_t length = readlink("/proc/self/exe", link, sizeof(link) - 1);
  if(length <= 0) return false;
  const std::string executable(link, static_cast<std::size_t>(length));
  const auto code = reinterpret_cast<std::uintptr_t>(&executable_is_this_program);
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while(std::getline(maps, line))
  {
    std::istringstream fields(line);
    std::string range, permissions, offset, device, inode, path;
    if(!(fields >> range >> permissions >> offset >> device >> inode)) continue;
    const std::size_t dash = range.find('-');
    if(dash == std::string::npos) continue;
    const std::uintptr_t begin = std::stoull(range.substr(0, dash), nullptr, 16);
    const std::uintptr_t end = std::stoull(range.substr(dash + 1), nullptr, 16);
    if(code < begin || code >= end) continue;
    std::getline(fields >> std::ws, path);
    return path == executable;
  }
  return false;
}
#endif

// Below this size of the mesh file the run takes under a second, and the
// rerun's second start of the process (some 45 ms: the shared libraries
// loaded again) costs more than the page faults it saves.
constexpr long long huge_pages_smallest_file = 4LL << 20;

// Runs the program again with malloc's huge pages, except where the user set
// GLIBC_TUNABLES (the rerun itself has it), where the mesh file is small
// (or unreadable: the read reports it), where the kernel gives no
// transparent huge pages, or under an address-space limit (where the
// program's behaviour is tested as it is). Called once the options are
// parsed, before anything is written, and not under an MPI launcher (which
// owns the processes' environment; the caller knows its variables). Nor in
// secure mode, nor where /proc/self/exe is not the program (started through
// the dynamic loader). Goes on as it is if the rerun fails.
#if defined(__linux__) && defined(__GLIBC__)
// The time, in nanoseconds, of the first touch of a fresh 4 KB page (a page
// fault), over 8 MB of anonymous memory kept from huge pages. Whether huge
// pages pay depends on it: where faults are expensive they save most of a
// large run's fault time, where they are cheap the huge pages' own first
// touch costs more than it saves (the hosts measured: benchmark README,
// "The program against its earlier builds").
inline double page_fault_ns()
{
  const std::size_t bytes = std::size_t(8) << 20;
  void* memory = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if(memory == MAP_FAILED) return 0.;
  madvise(memory, bytes, MADV_NOHUGEPAGE);
  volatile char* pages = static_cast<volatile char*>(memory);
  const auto start = std::chrono::steady_clock::now();
  for(std::size_t i = 0; i < bytes; i += 4096) pages[i] = 1;
  const double elapsed = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  munmap(memory, bytes);
  return elapsed / static_cast<double>(bytes / 4096);
}
#endif

// Above this cost of a page fault (--huge-pages auto) the program reruns
// with huge pages: between the costs of the hosts measured.
constexpr double huge_pages_fault_ns = 5000.;

// `when`: "on" reruns wherever the conditions below allow, "auto" only
// where a page fault is expensive (page_fault_ns()).
inline void rerun_with_huge_pages(char** argv, const std::string& mesh_file, const std::string& when)
{
#if defined(__linux__) && defined(__GLIBC__)
  if(std::getenv("GLIBC_TUNABLES") != nullptr || secure_mode()) return;
  struct stat file{};
  if(stat(mesh_file.c_str(), &file) != 0 || static_cast<long long>(file.st_size) < huge_pages_smallest_file) return;
  rlimit limit{};
  if(getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur != RLIM_INFINITY) return;
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string setting;
  if(!std::getline(mode, setting) || setting.find("[never]") != std::string::npos) return;
  if(!executable_is_this_program()) return;
  if(when == "auto" && !(page_fault_ns() > huge_pages_fault_ns)) return;
  if(setenv("GLIBC_TUNABLES", huge_pages_tunable, 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("GLIBC_TUNABLES");  // the rerun failed: go on with the kernel's default pages
#else
  (void)argv;
  (void)mesh_file;
  (void)when;
#endif
}

#endif
