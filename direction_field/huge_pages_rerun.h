// The program's memory pages (--huge-pages, direction_field/README.md).
//
// Most of a large run's memory is written once, fresh from the kernel, and on
// virtual machines a page fault is expensive: on the 2-core machines of the
// benchmark (benchmark/.../README.md, "Huge pages for the program") the faults
// of 4 KB pages took a fifth of the wall time of a field at 400k and 1.6M
// faces. glibc (2.35 or later) gives transparent huge pages to every large
// allocation of a process started with GLIBC_TUNABLES=glibc.malloc.hugetlb=1,
// a setting it reads only at start: so the program runs itself again with
// it. A library must not choose its process's allocator; the program is the
// process, so it may. Results are the same bit for bit; only the time changes.
#ifndef SMDF_DIRECTION_FIELD_HUGE_PAGES_RERUN_H
#define SMDF_DIRECTION_FIELD_HUGE_PAGES_RERUN_H

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#if defined(__linux__) && defined(__GLIBC__)
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

constexpr const char* huge_pages_tunable = "glibc.malloc.hugetlb=1";

// Whether this process's malloc was asked for transparent huge pages.
inline bool malloc_uses_huge_pages()
{
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return tunables != nullptr && std::strstr(tunables, huge_pages_tunable) != nullptr;
}

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
// owns the processes' environment; the caller knows its variables). Goes on
// as it is if the rerun fails.
inline void rerun_with_huge_pages(char** argv, const std::string& mesh_file)
{
#if defined(__linux__) && defined(__GLIBC__)
  if(std::getenv("GLIBC_TUNABLES") != nullptr) return;
  struct stat file{};
  if(stat(mesh_file.c_str(), &file) != 0 || static_cast<long long>(file.st_size) < huge_pages_smallest_file) return;
  rlimit limit{};
  if(getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur != RLIM_INFINITY) return;
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string setting;
  if(!std::getline(mode, setting) || setting.find("[never]") != std::string::npos) return;
  if(setenv("GLIBC_TUNABLES", huge_pages_tunable, 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("GLIBC_TUNABLES");  // the rerun failed: go on with the kernel's default pages
#else
  (void)argv;
  (void)mesh_file;
#endif
}

#endif
