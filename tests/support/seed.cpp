#include "support/seed.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace exactgeo::testing {

std::uint64_t test_seed() {
  constexpr std::uint64_t kDefaultSeed = 20261121;
  const char* text = std::getenv("EXACTGEO_TEST_SEED");
  if (text == nullptr || *text == '\0') return kDefaultSeed;
  return std::stoull(text, nullptr, 0);
}

std::mt19937_64 seeded_engine(std::string_view stream) {
  const std::uint64_t seed = test_seed();
  // FNV-1a of the stream name, so each test gets its own reproducible sequence.
  std::uint64_t h = 1469598103934665603ull;
  for (const char c : stream) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  std::cout << "[ seed     ] EXACTGEO_TEST_SEED=" << seed << " (stream " << stream << ")\n";
  ::testing::Test::RecordProperty("seed", std::to_string(seed));
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(h), static_cast<std::uint32_t>(h >> 32)};
  return std::mt19937_64(seq);
}

}  // namespace exactgeo::testing
