// The resident memory of this process, for the benchmarks (Linux /proc).
#ifndef SMDF_BENCHMARK_PROCESS_MEMORY_H
#define SMDF_BENCHMARK_PROCESS_MEMORY_H

#include <fstream>
#include <string>

// VmHWM (the peak) or VmRSS of this process, in MB (0 if /proc is not there).
inline double proc_status_mb(const std::string& key)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, key.size(), key) == 0)
      return std::stod(line.substr(key.size() + 1)) / 1024.;  // kB
  return 0.;
}

inline void reset_peak_memory()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";  // Linux >= 4.0: reset the peak RSS to the current RSS
}

#endif // SMDF_BENCHMARK_PROCESS_MEMORY_H
