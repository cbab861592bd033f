#include "cli/peak_memory.hpp"

#include <sys/resource.h>

namespace exactgeo::cli {

std::optional<std::size_t> peak_resident_bytes() noexcept {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0 || usage.ru_maxrss <= 0) return std::nullopt;
  // Linux reports ru_maxrss in kibibytes (getrusage(2)).
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;
}

}  // namespace exactgeo::cli
