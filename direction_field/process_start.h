// What the program checks of its process before it reads anything: the
// standard streams it may write to, and whether it can start its threads.
#ifndef SMDF_DIRECTION_FIELD_PROCESS_START_H
#define SMDF_DIRECTION_FIELD_PROCESS_START_H

#include <string>
#include <system_error>
#include <thread>
#include <vector>

#if defined(__unix__)
#include <cerrno>
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>
#endif

// A standard stream closed by the caller (2>&-) would give its number to the
// first file the program opens, and what is meant for the stream (a
// warning, the summary) would land in that file. Each closed one is opened
// on /dev/null: standard error for writing (its messages are lost, as the
// caller asked), standard input and output for reading only, so that writing
// the summary still fails as on a closed stream and is reported.
inline void open_closed_standard_streams()
{
#if defined(__unix__)
  for(int fd = 0; fd <= 2; ++fd)
  {
    if(fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int opened = open("/dev/null", fd == 2 ? O_WRONLY : O_RDONLY);
    if(opened >= 0 && opened != fd)  // the lowest free number is fd: this does not happen
    {
      dup2(opened, fd);
      close(opened);
    }
  }
#endif
}

// Under a small limit of processes (ulimit -u counts threads), a library
// that cannot start a thread ends the process with its own message
// (OpenMP's "libgomp: Thread creation failed"). So where such a limit is
// set, the program first starts as many threads as the machine has cores,
// and says in its own words when it cannot. Empty where it can.
inline std::string threads_cannot_start()
{
#if defined(__unix__)
  rlimit limit{};
  if(getrlimit(RLIMIT_NPROC, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::string();
  const unsigned count = std::thread::hardware_concurrency() > 0 ? std::thread::hardware_concurrency() : 1;
  std::vector<std::thread> started;
  std::string failure;
  try
  {
    for(unsigned i = 0; i < count; ++i) started.emplace_back([] {});
  }
  catch(const std::system_error&)
  {
    failure = "cannot start " + std::to_string(count) + " threads (the limit of processes, ulimit -u, is " +
              std::to_string(static_cast<unsigned long long>(limit.rlim_cur)) + "): raise it";
  }
  for(std::thread& t : started) t.join();
  return failure;
#else
  return std::string();
#endif
}

#endif
