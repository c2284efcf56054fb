// What a run of direction_field is doing, said on stderr while it does it
// (when stderr is a terminal and --quiet is not given), and the time of the
// program's own steps (reading, repair, writing) for the JSON.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_PROGRESS_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_PROGRESS_H

#include <chrono>
#include <cstdio>
#include <string>
#include <unistd.h>

class Progress
{
public:
  explicit Progress(bool quiet) : talk_(!quiet && ::isatty(STDERR_FILENO) == 1) {}

  // The step under way ("" between steps), for an error message.
  const std::string& step() const { return step_; }

  // Ends the line of the step under way, so that an error gets a line of its own.
  void interrupt()
  {
    if(talk_ && !step_.empty()) std::fprintf(stderr, "\n");
    step_.clear();
  }

  bool talks() const { return talk_; }

  // Starts a step; its time goes to `milliseconds` when end() is called.
  void begin(const std::string& what, double& milliseconds)
  {
    target_ = &milliseconds;
    step_ = what;
    start_ = std::chrono::steady_clock::now();
    if(talk_) std::fprintf(stderr, "direction_field: %s ...", what.c_str());
    if(talk_) std::fflush(stderr);
  }
  void end()
  {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    if(target_) *target_ += ms;
    target_ = nullptr;
    if(talk_ && percent_shown_) std::fprintf(stderr, "\rdirection_field: %s ... %.0f ms    \n", step_.c_str(), ms);
    else if(talk_) std::fprintf(stderr, " %.0f ms\n", ms);
    step_.clear();
    percent_shown_ = false;
  }
  // The fraction done within the step (the library's progress_callback), shown
  // on the step's line as a percentage, at most four times a second. Always
  // true: the run goes on.
  bool fraction(double done)
  {
    if(!talk_ || step_.empty()) return true;
    const auto now = std::chrono::steady_clock::now();
    if(percent_shown_ && now - shown_at_ < std::chrono::milliseconds(250)) return true;
    shown_at_ = now;
    percent_shown_ = true;
    std::fprintf(stderr, "\rdirection_field: %s ... %3.0f%%", step_.c_str(), 100. * done);
    std::fflush(stderr);
    return true;
  }
  // A line of its own (the library's steps, reported as they happen).
  void say(const std::string& line) const
  {
    if(talk_) std::fprintf(stderr, "direction_field: %s\n", line.c_str());
  }

private:
  bool talk_;
  double* target_ = nullptr;
  std::string step_;
  std::chrono::steady_clock::time_point start_, shown_at_;
  bool percent_shown_ = false;
};

// The program's own steps, in milliseconds.
struct Program_timings
{
  double read = 0., repair = 0., write = 0.;
  double io() const { return read + repair + write; }
};

#endif
