#pragma once

// One line of progress on a terminal's standard error, rewritten in place: what is being
// done, how much of it, and how fast, e.g.
//     building the search structure (187,392 faces)...
//     1,245,184 / 5,000,000 points (24.9%), 2.41M points/s
// The count's total is optional (standard input has none); so is the percentage.

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>

namespace exactgeo::cli {

/// "1,245,184 / 5,000,000 points (24.9%), 2.41M points/s": `done` of `total` (if known)
/// `unit`s after `seconds`; the rate is left out until some time has passed. `fraction`,
/// when given, is the share done when it is known otherwise than by counting (bytes of a
/// text file read).
std::string progress_text(std::uint64_t done, std::optional<std::uint64_t> total,
                          std::optional<double> fraction, double seconds, std::string_view unit);

/// "1,245,184"
std::string grouped(std::uint64_t n);

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;

  /// Writes nothing when `enabled` is false (standard error is not a terminal).
  ProgressLine(std::ostream& err, bool enabled, std::string unit);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// A task of the run without a count ("reading the mesh..."); it stays until the next
  /// update. The rate of the counts that follow is measured from here.
  void task(std::string_view what);
  /// The count so far; redrawn at most ten times a second. The rate counts from the last
  /// task, or from construction.
  void count(std::uint64_t done, std::optional<std::uint64_t> total,
             std::optional<double> fraction = std::nullopt);
  /// Erases the line (also done on destruction).
  void clear();

 private:
  void draw(const std::string& text);

  std::ostream& err_;
  bool enabled_;
  std::string unit_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_{};
  bool shown_ = false;
};

}  // namespace exactgeo::cli
