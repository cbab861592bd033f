#pragma once

// Progress on standard error: what is being done, how much of it, and how fast, e.g.
//     building the search structure (187,392 faces)...
//     1,245,184 / 5,000,000 points (24.9%), 2.41M points/s
// The count's total is optional (standard input has none); so is the percentage. On a
// terminal it is one line rewritten in place and erased at the end; asked for elsewhere
// (--progress: a log, a notebook) each update is a line of its own, at most one a second.

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

/// How progress is shown.
enum class ProgressMode : std::uint8_t {
  off,       ///< not at all (standard error is not a terminal, and --progress was not given)
  terminal,  ///< one line rewritten in place, erased at the end
  lines,     ///< a line per update, kept: for logs and notebooks (--progress)
};

/// The mode for standard error: a terminal's, else lines when `asked` (--progress), else off.
ProgressMode progress_mode(bool asked, bool terminal) noexcept;

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;

  ProgressLine(std::ostream& err, ProgressMode mode, std::string unit);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// A task of the run without a count ("reading the mesh..."); it stays until the next
  /// update. The rate of the counts that follow is measured from here.
  void task(std::string_view what);
  /// The count so far; redrawn at most ten times a second on a terminal, written at most
  /// once a second as lines (and when the total is reached). The rate counts from the last
  /// task, or from construction.
  void count(std::uint64_t done, std::optional<std::uint64_t> total,
             std::optional<double> fraction = std::nullopt);
  /// Erases the line on a terminal (also done on destruction), before other messages and
  /// at the end; as lines, writes the latest count if it was held back, so that a log ends
  /// with the final one.
  void clear();

 private:
  void draw(const std::string& text);

  std::ostream& err_;
  ProgressMode mode_;
  std::string unit_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_{};
  bool shown_ = false;    ///< terminal: a line is on the screen
  bool counted_ = false;  ///< a count has been written since the last task
  std::string held_;      ///< lines: the latest count, not yet written
};

}  // namespace exactgeo::cli
