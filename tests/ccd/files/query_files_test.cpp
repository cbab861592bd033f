// Reading the CCD benchmark format exactly.

#include "exactgeo/ccd/files/query_files.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "exactgeo/io/input_error.hpp"

namespace exactgeo::ccd {
namespace {

double ratio(std::string_view num, std::string_view den) {
  std::string error;
  const auto x = exact_ratio(num, den, error);
  EXPECT_TRUE(x.has_value()) << error;
  return x.value_or(NAN);
}

bool refused(std::string_view num, std::string_view den) {
  std::string error;
  return !exact_ratio(num, den, error).has_value() && !error.empty();
}

TEST(ExactRatio, IntegersOfAnySizeWhoseRatioIsADouble) {
  EXPECT_EQ(ratio("6004799503160661", "36028797018963968"), 6004799503160661.0 / 0x1p55);
  EXPECT_EQ(ratio("-3", "4"), -0.75);
  EXPECT_EQ(ratio("0", "7"), 0.0);
  // Beyond 64 bits: 3 * 2^100 / 2^98 = 12, and 2^-1074 as 1 / 2^1074.
  EXPECT_EQ(ratio("3802951800684688204490109616128", "316912650057057350374175801344"), 12.0);
  const std::string two_to_1074 = [] {
    mpz_class z = 1;
    z <<= 1074;
    return z.get_str();
  }();
  EXPECT_EQ(ratio("1", two_to_1074), std::nextafter(0.0, 1.0));
  EXPECT_EQ(ratio("+5", "-10"), -0.5);
  // A zero keeps the sign of the quotient as written.
  EXPECT_TRUE(std::signbit(ratio("-0", "1")));
  EXPECT_TRUE(std::signbit(ratio("0", "-8")));
  EXPECT_FALSE(std::signbit(ratio("-0", "-8")));
  EXPECT_FALSE(std::signbit(ratio("+0", "1")));
}

TEST(ExactRatio, RefusesWhatIsNotExactlyADouble) {
  EXPECT_TRUE(refused("1", "3"));                 // not dyadic
  EXPECT_TRUE(refused("9007199254740993", "1"));  // 2^53 + 1: 54 significant bits
  EXPECT_TRUE(refused("1", "0"));
  EXPECT_TRUE(refused("1.5", "2"));
  EXPECT_TRUE(refused("", "2"));
  EXPECT_TRUE(refused("0x10", "2"));
  EXPECT_TRUE(refused("1", "2 3"));
  mpz_class huge = 1;
  huge <<= 1100;
  EXPECT_TRUE(refused(huge.get_str(), "1"));  // overflows
  EXPECT_TRUE(refused("1", huge.get_str()));  // underflows
}

TEST(QueryRecords, SevenColumnFileWithTruth) {
  std::ostringstream text;
  for (int row = 0; row < 16; ++row) {
    text << row << ",1," << -row << ",2,0,1," << (row < 8 ? 1 : 0) << "\n";
  }
  std::istringstream in(text.str());
  const auto records = read_query_records(in, "q.csv");
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].truth, true);
  EXPECT_EQ(records[1].truth, false);
  EXPECT_EQ(records[1].points[3], (Point3{11, -5.5, 0}));
  const ccd::EdgeEdgeQuery q = edge_edge_query(records[1]);
  EXPECT_EQ(q.eb1_t0, (Point3{11, -5.5, 0}));
  EXPECT_EQ(q.eb1_t1, (Point3{15, -7.5, 0}));
}

TEST(QueryRecords, SixColumnFileHasNoTruth) {
  std::ostringstream text;
  for (int row = 0; row < 8; ++row)
    text << "1,2,3,4,5,8\n";
  std::istringstream in(text.str());
  const auto records = read_query_records(in, "q.csv");
  ASSERT_EQ(records.size(), 1u);
  EXPECT_FALSE(records[0].truth.has_value());
  EXPECT_EQ(records[0].points[7], (Point3{0.5, 0.75, 0.625}));
}

void expect_error(const std::string& text, const std::string& message) {
  std::istringstream in(text);
  try {
    read_query_records(in, "q.csv");
    FAIL() << "no error for " << text;
  } catch (const io::InputError& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(QueryRecords, ErrorsNameTheLine) {
  expect_error("1,1,1,1,1\n", "q.csv:1: expected 6 or 7 comma-separated fields, found 5");
  expect_error("1,1,1,1,1,1,1\n1,1,1,1,1,1\n",
               "q.csv:2: expected 7 fields like the first row, found 6");
  expect_error("1,3,1,1,1,1\n", "q.csv:1: '1/3' is not exactly a finite double");
  expect_error("1,1,1,1,1,1,2\n", "q.csv:1: ground truth must be 0 or 1");
  expect_error("1,1,1,1,1,1,1\n1,1,1,1,1,1,0\n",
               "q.csv:2: ground truth differs between rows of one query");
  expect_error("1,1,1,1,1,1\n1,1,1,1,1,1\n", "q.csv:2: the last query has 2 rows, not 8");
  expect_error("a,1,1,1,1,1\n", "q.csv:1: 'a/1' is not a ratio of integers");
}

TEST(TruthArray, ParsesAndRefuses) {
  std::istringstream ok(" [true,false, true ]\n");
  EXPECT_EQ(read_truth_array(ok, "t.json"), (std::vector<bool>{true, false, true}));
  std::istringstream empty("[]");
  EXPECT_TRUE(read_truth_array(empty, "t.json").empty());
  for (const char* bad : {"", "[", "[true", "[true,]", "[1]", "[true] x", "{}"}) {
    std::istringstream in(bad);
    EXPECT_THROW(read_truth_array(in, "t.json"), io::InputError) << bad;
  }
}

TEST(QueryRecords, BundledBenchmarkFilesRead) {
  const std::string path =
      std::string(EXACTGEO_TEST_DATA_DIR) + "/ccd/sample-queries/unit-tests/edge-edge/data_0_0.csv";
  std::ifstream lines(path);
  std::size_t rows = 0;
  for (std::string line; std::getline(lines, line);)
    rows += !line.empty();
  std::ifstream file(path);
  ASSERT_TRUE(file);
  const auto records = read_query_records(file, "data_0_0.csv");
  EXPECT_EQ(records.size() * 8, rows);
  EXPECT_GT(records.size(), 10u);
  for (const auto& r : records)
    EXPECT_TRUE(r.truth.has_value());
}

/// A type that contradicts the path, and a truth file for files that carry their own
/// truth column, are refused with the file named; the path's own type is used as before.
TEST(QueryFiles, RefuseATypeOrTruthFileThatContradictsTheFile) {
  const std::string folder = std::string(EXACTGEO_TEST_DATA_DIR) + "/ccd/sample-queries/unit-tests";
  const std::string edges = folder + "/edge-edge";
  auto message = [](auto&& read) {
    try {
      read();
    } catch (const io::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string type_error =
      message([&] { read_query_files({edges}, QueryType::vertex_face); });
  EXPECT_NE(type_error.find("edge-edge/data_0_0.csv"), std::string::npos) << type_error;
  EXPECT_NE(type_error.find("edge-edge queries by its path"), std::string::npos) << type_error;
  const std::string truth_error =
      message([&] { read_query_files({edges}, std::nullopt, "x.json"); });
  EXPECT_NE(truth_error.find("has its own truth column"), std::string::npos) << truth_error;
  // The same type as the path, or none, reads the files.
  EXPECT_FALSE(read_query_files({edges}, QueryType::edge_edge).empty());
  EXPECT_EQ(read_query_files({folder}).size(), 2u * read_query_files({edges}).size());
}

}  // namespace
}  // namespace exactgeo::ccd
