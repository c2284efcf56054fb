// What a run of direction_field is doing, said on stderr while it does it
// (when stderr is a terminal and --quiet is not given), and the time of the
// program's own steps (reading, repair, writing) for the JSON.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_PROGRESS_H
#define SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_PROGRESS_H

#include <chrono>
#include <cstdio>
#include <string>
#include <unistd.h>

class Progress
{
public:
  explicit Progress(bool quiet) : talk_(!quiet && ::isatty(STDERR_FILENO) == 1) {}

  bool talks() const { return talk_; }

  // Starts a step; its time goes to `milliseconds` when end() is called.
  void begin(const std::string& what, double& milliseconds)
  {
    target_ = &milliseconds;
    start_ = std::chrono::steady_clock::now();
    if(talk_) std::fprintf(stderr, "direction_field: %s ...", what.c_str());
    if(talk_) std::fflush(stderr);
  }
  void end()
  {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    if(target_) *target_ += ms;
    target_ = nullptr;
    if(talk_) std::fprintf(stderr, " %.0f ms\n", ms);
  }
  // A line of its own (the library's steps, reported as they happen).
  void say(const std::string& line) const
  {
    if(talk_) std::fprintf(stderr, "direction_field: %s\n", line.c_str());
  }

private:
  bool talk_;
  double* target_ = nullptr;
  std::chrono::steady_clock::time_point start_;
};

// The program's own steps, in milliseconds.
struct Program_timings
{
  double read = 0., repair = 0., write = 0.;
  double io() const { return read + repair + write; }
};

#endif
