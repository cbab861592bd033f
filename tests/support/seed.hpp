#pragma once

#include <cstdint>
#include <random>
#include <string_view>

namespace exactgeo::testing {

/// The seed of every randomized test: EXACTGEO_TEST_SEED from the environment when set,
/// otherwise a fixed default, so CI is reproducible and a failure can be replayed or a
/// new seed explored. The seed is printed (and recorded as a test property) by
/// seeded_engine().
std::uint64_t test_seed();

/// A generator seeded with test_seed() mixed with `stream` (one stream per test, so that
/// adding a test does not change the inputs of the others). Prints the seed.
std::mt19937_64 seeded_engine(std::string_view stream);

}  // namespace exactgeo::testing
