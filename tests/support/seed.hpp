#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <string_view>

namespace exactgeo::testing {

/// The seed of every randomized test: EXACTGEO_TEST_SEED from the environment when set,
/// otherwise a fixed default, so CI is reproducible and a failure can be replayed or a
/// new seed explored. The seed is printed (and recorded as a test property) by
/// seeded_engine().
std::uint64_t test_seed();

/// The effort of randomized tests: EXACTGEO_TEST_EFFORT from the environment, a number in
/// (0, 1], 1 when unset or empty. Anything else (text that is not a number, 0, negative,
/// above 1, not finite) throws std::invalid_argument naming the variable and its value,
/// so a mistyped effort fails the test instead of quietly running at full effort.
/// Printed beside the seed (and recorded as a test property) by seeded_engine() when it
/// is not 1.
double test_effort();

/// The number of trials of a randomized loop at the effort of test_effort(): `full` at
/// effort 1 (exactly: every test then runs as without the knob), otherwise
/// round(full * effort) but at least `least` (chosen by the caller so that every family of
/// the loop is still driven) and never more than `full`. The sanitizer run of CI uses a
/// quarter: the sanitizers look at memory and undefined behaviour on the code paths, which
/// the fewer trials still drive, while the Release suite runs the full counts.
std::size_t scaled_trials(std::size_t full, std::size_t least = 1);

/// A generator seeded with test_seed() mixed with `stream` (one stream per test, so that
/// adding a test does not change the inputs of the others). Prints the seed.
std::mt19937_64 seeded_engine(std::string_view stream);

}  // namespace exactgeo::testing
