// Locations (location.hpp): each has its own name, the one the command line and Python
// print (the enumerator's), and LocationCounts counts each location apart, from zero,
// against a tally kept by hand over a random sequence.

#include "exactgeo/inside/location.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <random>
#include <set>
#include <string>
#include <string_view>

#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

constexpr std::array kLocations{Location::outside, Location::inside, Location::boundary,
                                Location::undecided};

TEST(Location, EachLocationIsNamedAsItsEnumerator) {
  EXPECT_EQ(to_string(Location::outside), "outside");
  EXPECT_EQ(to_string(Location::inside), "inside");
  EXPECT_EQ(to_string(Location::boundary), "boundary");
  EXPECT_EQ(to_string(Location::undecided), "undecided");
  std::set<std::string_view> names;
  for (const Location l : kLocations)
    names.insert(to_string(l));
  EXPECT_EQ(names.size(), kLocations.size());
}

TEST(Location, EachNameReadsBackAndNoOtherWordDoes) {
  for (const Location l : kLocations)
    EXPECT_EQ(location_named(to_string(l)), l);
  for (const std::string_view word : {"", "Inside", "inside ", "outsid", "?", "in side"})
    EXPECT_FALSE(location_named(word).has_value()) << word;
}

TEST(Location, CountsStartAtZeroAndCountEachLocationApart) {
  LocationCounts counts;
  for (const Location l : kLocations)
    EXPECT_EQ(counts[l], 0u);
  auto rng = testing::seeded_engine("inside.location.counts");
  std::uniform_int_distribution<std::size_t> pick(0, kLocations.size() - 1);
  std::array<std::size_t, 4> tally{};
  for (int i = 0; i < 1000; ++i) {
    const std::size_t k = pick(rng);
    counts.add(kLocations[k]);
    ++tally[k];
  }
  std::size_t total = 0;
  for (std::size_t k = 0; k < kLocations.size(); ++k) {
    EXPECT_EQ(counts[kLocations[k]], tally[k]) << to_string(kLocations[k]);
    total += counts[kLocations[k]];
  }
  EXPECT_EQ(total, 1000u);
}

}  // namespace
}  // namespace exactgeo::inside
