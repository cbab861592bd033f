#include "cli/progress_line.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace exactgeo::cli {
namespace {

TEST(ProgressText, CountsWithThousandsSeparators) {
  EXPECT_EQ(grouped(0), "0");
  EXPECT_EQ(grouped(999), "999");
  EXPECT_EQ(grouped(1000), "1,000");
  EXPECT_EQ(grouped(1245184), "1,245,184");
  EXPECT_EQ(grouped(18446744073709551615ull), "18,446,744,073,709,551,615");
}

TEST(ProgressText, PercentAndRateWhereTheTotalIsKnown) {
  EXPECT_EQ(progress_text(1245184, 5000000, std::nullopt, 0.5, "points"),
            "1,245,184 / 5,000,000 points (24.9%), 2.49M points/s");
  EXPECT_EQ(progress_text(500, 1000, std::nullopt, 2.0, "queries"),
            "500 / 1,000 queries (50.0%), 250 queries/s");
  EXPECT_EQ(progress_text(12345, 12345, std::nullopt, 1.0, "queries"),
            "12,345 / 12,345 queries (100.0%), 12.3k queries/s");
}

TEST(ProgressText, NoTotalNoPercentUnlessAFractionIsGiven) {
  EXPECT_EQ(progress_text(70000, std::nullopt, std::nullopt, 1.0, "points"),
            "70,000 points, 70k points/s");
  // A text file's share comes from its bytes, not from a count of points.
  EXPECT_EQ(progress_text(70000, std::nullopt, 0.25, 1.0, "points"),
            "70,000 points (25.0%), 70k points/s");
}

TEST(ProgressText, NoRateBeforeAnyTimeHasPassed) {
  EXPECT_EQ(progress_text(10, 20, std::nullopt, 0.0, "queries"), "10 / 20 queries (50.0%)");
  EXPECT_EQ(progress_text(0, 0, std::nullopt, 0.0, "queries"), "0 / 0 queries");
}

TEST(ProgressLine, WritesNothingWhenDisabled) {
  std::ostringstream err;
  {
    ProgressLine line(err, ProgressMode::off, "points");
    line.task("building");
    line.count(5, 10);
    line.clear();
  }
  EXPECT_EQ(err.str(), "");
}

TEST(ProgressLine, RewritesOneLineAndErasesItAtTheEnd) {
  std::ostringstream err;
  {
    ProgressLine line(err, ProgressMode::terminal, "points");
    line.task("building the search structure (6 faces)");
    line.count(10, 10);  // finished: drawn whatever the time since the last drawing
  }
  const std::string text = err.str();
  EXPECT_EQ(text.find("\r\033[Kbuilding the search structure (6 faces)...\r\033[K10 / 10 points "
                      "(100.0%)"),
            0u)
      << text;
  EXPECT_EQ(text.substr(text.size() - 4), "\r\033[K");  // erased on destruction
  EXPECT_EQ(text.find('\n'), std::string::npos);        // never a new line
}

TEST(ProgressLine, TheModeIsTheTerminalsOrAskedFor) {
  EXPECT_EQ(progress_mode(false, true), ProgressMode::terminal);
  EXPECT_EQ(progress_mode(true, true), ProgressMode::terminal);
  EXPECT_EQ(progress_mode(true, false), ProgressMode::lines);
  EXPECT_EQ(progress_mode(false, false), ProgressMode::off);
}

TEST(ProgressLine, AsLinesForALogEveryUpdateIsALineAndTheLastCountIsKept) {
  std::ostringstream err;
  {
    ProgressLine line(err, ProgressMode::lines, "points");
    line.task("reading mesh.obj");
    line.count(5, std::nullopt);  // the first count of a task: written at once
    line.count(6, std::nullopt);  // within the second: held back
    line.count(7, std::nullopt);
    line.clear();  // the end: the latest count is written
    line.clear();  // once
    line.task("classifying");
    line.count(9, 9);
  }
  EXPECT_EQ(err.str(),
            "reading mesh.obj...\n5 points\n7 points\nclassifying...\n9 / 9 points (100.0%)\n");
}

}  // namespace
}  // namespace exactgeo::cli
