#include "cli/progress_line.hpp"

#include <cstdio>
#include <ostream>

namespace exactgeo::cli {

std::string grouped(std::uint64_t n) {
  std::string digits = std::to_string(n);
  std::string text;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text.push_back(',');
    text.push_back(digits[i]);
  }
  return text;
}

namespace {

/// "2.41M", "815k", "12.0": three significant digits are plenty for a rate.
std::string rate_text(double per_second) {
  const char* suffix = "";
  if (per_second >= 1e6) {
    per_second /= 1e6;
    suffix = "M";
  } else if (per_second >= 1e3) {
    per_second /= 1e3;
    suffix = "k";
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, per_second < 100 ? "%.3g%s" : "%.0f%s", per_second, suffix);
  return buffer;
}

}  // namespace

std::string progress_text(std::uint64_t done, std::optional<std::uint64_t> total,
                          std::optional<double> fraction, double seconds, std::string_view unit) {
  std::string text = grouped(done);
  if (total) text.append(" / ").append(grouped(*total));
  text.append(" ").append(unit);
  if (!fraction && total && *total > 0)
    fraction = static_cast<double>(done) / static_cast<double>(*total);
  if (fraction) {
    char percent[32];
    std::snprintf(percent, sizeof percent, " (%.1f%%)", 100.0 * *fraction);
    text.append(percent);
  }
  if (seconds >= 0.05) {
    text.append(", ").append(rate_text(static_cast<double>(done) / seconds));
    text.append(" ").append(unit).append("/s");
  }
  return text;
}

ProgressMode progress_mode(bool asked, bool terminal) noexcept {
  if (terminal) return ProgressMode::terminal;
  return asked ? ProgressMode::lines : ProgressMode::off;
}

ProgressLine::ProgressLine(std::ostream& err, ProgressMode mode, std::string unit)
    : err_(err), mode_(mode), unit_(std::move(unit)) {}

ProgressLine::~ProgressLine() {
  clear();
}

void ProgressLine::task(std::string_view what) {
  if (mode_ == ProgressMode::off) return;
  clear();  // as lines: the task before ends with its latest count
  start_ = Clock::now();
  std::string text(what);
  text.append("...");
  draw(text);
  counted_ = false;
}

void ProgressLine::count(std::uint64_t done, std::optional<std::uint64_t> total,
                         std::optional<double> fraction) {
  if (mode_ == ProgressMode::off) return;
  const Clock::time_point now = Clock::now();
  const bool finished = total && done >= *total;
  const auto interval = mode_ == ProgressMode::terminal ? std::chrono::milliseconds(100)
                                                        : std::chrono::milliseconds(1000);
  const double seconds = std::chrono::duration<double>(now - start_).count();
  std::string text = progress_text(done, total, fraction, seconds, unit_);
  if (counted_ && !finished && now - last_draw_ < interval) {
    if (mode_ == ProgressMode::lines) held_ = std::move(text);
    return;
  }
  last_draw_ = now;
  counted_ = true;
  held_.clear();
  draw(text);
}

void ProgressLine::clear() {
  if (mode_ == ProgressMode::lines && !held_.empty()) {
    draw(held_);
    held_.clear();
  }
  if (mode_ != ProgressMode::terminal || !shown_) return;
  err_ << "\r\033[K" << std::flush;
  shown_ = false;
}

void ProgressLine::draw(const std::string& text) {
  if (mode_ == ProgressMode::lines) {
    err_ << text << "\n" << std::flush;
    return;
  }
  err_ << "\r\033[K" << text << std::flush;  // erase the rest of a longer earlier line
  shown_ = true;
}

}  // namespace exactgeo::cli
