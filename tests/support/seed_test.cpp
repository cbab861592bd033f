#include "support/seed.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>

namespace exactgeo::testing {
namespace {

/// Sets EXACTGEO_TEST_EFFORT (or unsets it) for the life of the object, then puts back
/// what was there (CI runs the suite with an effort of its own).
class EffortVariable {
 public:
  explicit EffortVariable(const char* value) {
    if (const char* old = std::getenv(kName)) old_ = old;
    if (value == nullptr) {
      ::unsetenv(kName);
    } else {
      ::setenv(kName, value, 1);
    }
  }
  ~EffortVariable() {
    if (old_) {
      ::setenv(kName, old_->c_str(), 1);
    } else {
      ::unsetenv(kName);
    }
  }
  EffortVariable(const EffortVariable&) = delete;
  EffortVariable& operator=(const EffortVariable&) = delete;

 private:
  static constexpr const char* kName = "EXACTGEO_TEST_EFFORT";
  std::optional<std::string> old_;
};

TEST(ScaledTrials, UnsetOrEmptyIsFullEffortAndEveryCountUnchanged) {
  for (const char* value : {static_cast<const char*>(nullptr), "", "1", "1.0"}) {
    const EffortVariable effort(value);
    EXPECT_EQ(test_effort(), 1.0);
    for (const std::size_t full : {0u, 1u, 3u, 7u, 1000u, 123457u}) {
      EXPECT_EQ(scaled_trials(full), full);
      // At full effort `least` never adds trials, even above `full`.
      EXPECT_EQ(scaled_trials(full, 10), full);
    }
  }
}

TEST(ScaledTrials, AQuarterRoundsAndKeepsTheLeast) {
  const EffortVariable effort("0.25");
  EXPECT_EQ(test_effort(), 0.25);
  EXPECT_EQ(scaled_trials(1000), 250u);
  EXPECT_EQ(scaled_trials(10), 3u);  // 2.5 rounds away from zero
  EXPECT_EQ(scaled_trials(9), 2u);   // 2.25
  EXPECT_EQ(scaled_trials(2), 1u);   // 0.5, and at least one
  EXPECT_EQ(scaled_trials(1), 1u);
  EXPECT_EQ(scaled_trials(40, 12), 12u);
  EXPECT_EQ(scaled_trials(400, 12), 100u);
  // Never more than the full count.
  EXPECT_EQ(scaled_trials(5, 12), 5u);
  EXPECT_EQ(scaled_trials(0), 0u);
}

TEST(ScaledTrials, SmallEffortsAndExponentNotation) {
  const EffortVariable effort("1e-3");
  EXPECT_EQ(test_effort(), 1e-3);
  EXPECT_EQ(scaled_trials(100000), 100u);
  EXPECT_EQ(scaled_trials(100), 1u);
  EXPECT_EQ(scaled_trials(100, 4), 4u);
}

TEST(ScaledTrials, AnythingButANumberInZeroToOneFailsLoudly) {
  for (const char* value :
       {"bogus", "0", "-0.5", "1.5", "2", "0.25x", " ", "nan", "inf", "1e999", "0x"}) {
    SCOPED_TRACE(value);
    const EffortVariable effort(value);
    EXPECT_THROW(test_effort(), std::invalid_argument);
    EXPECT_THROW(scaled_trials(100), std::invalid_argument);
    EXPECT_THROW(seeded_engine("support.seed.effort"), std::invalid_argument);
    try {
      test_effort();
    } catch (const std::invalid_argument& error) {
      // The message names the variable and the value given.
      EXPECT_NE(std::string(error.what()).find("EXACTGEO_TEST_EFFORT"), std::string::npos);
      EXPECT_NE(std::string(error.what()).find(value), std::string::npos);
    }
  }
}

TEST(ScaledTrials, TheSeedStreamDoesNotDependOnTheEffort) {
  std::uint64_t full = 0;
  {
    const EffortVariable effort(nullptr);
    full = seeded_engine("support.seed.stream")();
  }
  const EffortVariable effort("0.25");
  EXPECT_EQ(seeded_engine("support.seed.stream")(), full);
}

}  // namespace
}  // namespace exactgeo::testing
