#pragma once

namespace exactgeo::cli {

/// The exit codes of every subcommand (DESIGN.md section 4).
enum class ExitCode : int {
  success = 0,
  found = 1,        ///< the run found what it checks for (ccd: a false negative)
  input_error = 2,  ///< usage or input error; the message is on stderr
};

constexpr int to_int(ExitCode code) noexcept {
  return static_cast<int>(code);
}

}  // namespace exactgeo::cli
