#pragma once

// The process's peak resident memory so far (the high-water mark of its resident set),
// for reports that state what a run needed.

#include <cstddef>
#include <optional>

namespace exactgeo::cli {

/// In bytes; nullopt where the system does not say (getrusage failed).
std::optional<std::size_t> peak_resident_bytes() noexcept;

}  // namespace exactgeo::cli
