#pragma once

namespace exactgeo::cli {

/// The exit codes of every subcommand (the command-line contract, README.md).
enum class ExitCode : int {
  success = 0,
  found = 1,        ///< the run found what it checks for (ccd: a false negative)
  input_error = 2,  ///< usage or input error; the message is on stderr
};

constexpr int to_int(ExitCode code) noexcept {
  return static_cast<int>(code);
}

}  // namespace exactgeo::cli
