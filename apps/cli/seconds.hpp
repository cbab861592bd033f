#pragma once

// The clock the command line's reports time with (steady: never jumps), and seconds since
// a point of it.

#include <chrono>

namespace exactgeo::cli {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace exactgeo::cli
