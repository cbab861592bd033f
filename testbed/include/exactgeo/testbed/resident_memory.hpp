#pragma once

// The process's peak resident memory, resettable (Linux): /proc/self/status's VmHWM is
// the high-water mark of its resident set, and writing 5 to /proc/self/clear_refs sets
// that mark back to the resident set of the moment. So the peak of one piece of work is
// read by resetting before it and reading after. Memory freed earlier but kept by the
// allocator is handed back first (glibc's malloc_trim), so that it is not counted.

#include <malloc.h>

#include <cstddef>
#include <fstream>
#include <optional>
#include <string>

namespace exactgeo::testbed {

/// Sets the peak back to the current resident set; false when the system does not allow it.
inline bool reset_peak_resident_memory() {
  malloc_trim(0);
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

/// The peak resident memory in bytes since the start or the last reset, if known.
inline std::optional<std::size_t> peak_resident_memory() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stoull(line.substr(6)) * 1024;  // "... kB"
  }
  return std::nullopt;
}

}  // namespace exactgeo::testbed
