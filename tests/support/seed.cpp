#include "support/seed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace exactgeo::testing {

std::uint64_t test_seed() {
  constexpr std::uint64_t kDefaultSeed = 20261121;
  const char* text = std::getenv("EXACTGEO_TEST_SEED");
  if (text == nullptr || *text == '\0') return kDefaultSeed;
  return std::stoull(text, nullptr, 0);
}

double test_effort() {
  const char* text = std::getenv("EXACTGEO_TEST_EFFORT");
  if (text == nullptr || *text == '\0') return 1.0;
  char* end = nullptr;
  errno = 0;
  const double effort = std::strtod(text, &end);
  // The whole text a number (no trailing characters, no range error), in (0, 1].
  if (end == text || *end != '\0' || errno != 0 || !std::isfinite(effort) || !(effort > 0.0) ||
      effort > 1.0) {
    throw std::invalid_argument("EXACTGEO_TEST_EFFORT=\"" + std::string(text) +
                                "\": the effort of randomized tests must be a number in (0, 1] "
                                "(unset means 1)");
  }
  return effort;
}

std::size_t scaled_trials(std::size_t full, std::size_t least) {
  const double effort = test_effort();
  if (effort == 1.0) return full;
  const auto scaled = static_cast<std::size_t>(std::llround(static_cast<double>(full) * effort));
  return std::min(full, std::max(least, scaled));
}

std::mt19937_64 seeded_engine(std::string_view stream) {
  const std::uint64_t seed = test_seed();
  const double effort = test_effort();
  // FNV-1a of the stream name, so each test gets its own reproducible sequence.
  std::uint64_t h = 1469598103934665603ull;
  for (const char c : stream) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  std::cout << "[ seed     ] EXACTGEO_TEST_SEED=" << seed;
  if (effort != 1.0) std::cout << " EXACTGEO_TEST_EFFORT=" << effort;
  std::cout << " (stream " << stream << ")\n";
  ::testing::Test::RecordProperty("seed", std::to_string(seed));
  if (effort != 1.0) {
    std::ostringstream text;
    text << effort;
    ::testing::Test::RecordProperty("effort", text.str());
  }
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(h), static_cast<std::uint32_t>(h >> 32)};
  return std::mt19937_64(seq);
}

}  // namespace exactgeo::testing
