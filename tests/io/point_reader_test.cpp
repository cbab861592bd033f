// Points in blocks: text, f64 and npy give the same points bit for bit, whatever the block
// size and byte order; every malformed binary input is refused naming the source, the
// point and its byte offset.

#include "exactgeo/io/point_reader.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "exactgeo/io/input_error.hpp"
#include "support/generators.hpp"
#include "support/npy_bytes.hpp"
#include "support/seed.hpp"

namespace exactgeo::io {
namespace {

using testing::float64_bytes;
using testing::npy_file;
using testing::npy_header;
using testing::npy_points_dict;
using Points = std::vector<PointXyz>;

/// Every point of `bytes` in `format`, read `block` at a time.
Points read_all(const std::string& bytes, PointFormat format, std::size_t block = 5) {
  std::istringstream in(bytes);
  PointReader reader(in, "pts", format);
  Points all;
  for (auto part = reader.read_block(block); !part.empty(); part = reader.read_block(block)) {
    EXPECT_LE(part.size(), block);
    all.insert(all.end(), part.begin(), part.end());
  }
  return all;
}

/// The message reading all of `bytes` throws ("" if none).
std::string refusal(const std::string& bytes, PointFormat format, std::size_t block = 5) {
  try {
    read_all(bytes, format, block);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_refused(const std::string& bytes, PointFormat format, const std::string& what,
                    std::size_t block = 5) {
  const std::string message = refusal(bytes, format, block);
  EXPECT_EQ(message, what);
}

/// Bitwise equality (so -0.0 and 0.0 differ).
void expect_same_bits(const Points& a, const Points& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a[i][c]), std::bit_cast<std::uint64_t>(b[i][c]))
          << "point " << i << " coordinate " << c;
    }
  }
}

/// Random points of every magnitude, with signed zeros, subnormals and the extremes.
Points awkward_points(std::size_t n) {
  auto rng = testing::seeded_engine("PointReader.awkward");
  Points points = {{-0.0, 0.0, DBL_MIN / 4}, {DBL_MAX, -DBL_MAX, DBL_TRUE_MIN}};
  while (points.size() < n) {
    const PointXyz p = testing::random_point(rng, 1.0);
    const int scale = testing::uniform_int(rng, -1000, 1000);
    points.push_back({std::ldexp(p[0], scale), std::ldexp(p[1], scale), p[2]});
  }
  return points;
}

std::string as_text(const Points& points) {
  std::string text = "# x y z\n";
  char line[128];
  for (const PointXyz& p : points) {
    std::snprintf(line, sizeof line, "%a %a,%a\n", p[0], p[1], p[2]);
    text += line;
  }
  return text;
}

TEST(PointFormat, NamesAndDefaults) {
  for (const PointFormat f : {PointFormat::text, PointFormat::f64, PointFormat::npy}) {
    EXPECT_EQ(parse_point_format(to_string(f)), f);
  }
  EXPECT_FALSE(parse_point_format("NPY").has_value());
  EXPECT_FALSE(parse_point_format("").has_value());
  EXPECT_EQ(default_point_format("points.npy"), PointFormat::npy);
  EXPECT_EQ(default_point_format("dir/POINTS.NpY"), PointFormat::npy);
  EXPECT_EQ(default_point_format(".npy"), PointFormat::npy);
  EXPECT_EQ(default_point_format("points.npy.txt"), PointFormat::text);
  EXPECT_EQ(default_point_format("npy"), PointFormat::text);
  EXPECT_EQ(default_point_format("points.f64"), PointFormat::text);
  EXPECT_EQ(default_point_format("-"), PointFormat::text);
}

TEST(PointReader, EveryFormatGivesTheSamePointsBitForBit) {
  const Points points = awkward_points(1000);
  const std::string f64 = float64_bytes(points);
  for (const std::size_t block :
       {std::size_t{1}, std::size_t{7}, std::size_t{1000}, std::size_t{4096}}) {
    SCOPED_TRACE("block " + std::to_string(block));
    expect_same_bits(read_all(as_text(points), PointFormat::text, block), points);
    expect_same_bits(read_all(f64, PointFormat::f64, block), points);
    for (const int major : {1, 2, 3}) {
      for (const bool big_endian : {false, true}) {
        SCOPED_TRACE("npy " + std::to_string(major) + (big_endian ? " >f8" : " <f8"));
        expect_same_bits(read_all(npy_file(points, major, big_endian), PointFormat::npy, block),
                         points);
      }
    }
  }
}

TEST(PointReader, EmptyInputs) {
  EXPECT_TRUE(read_all("", PointFormat::f64).empty());
  EXPECT_TRUE(read_all("", PointFormat::text).empty());
  EXPECT_TRUE(read_all(npy_file({}), PointFormat::npy).empty());
  expect_refused("", PointFormat::npy, "pts: header: the input is empty, not an .npy file");
}

TEST(PointReader, TextErrorsNameTheLine) {
  expect_refused("1 2 3\n\n1 2\n", PointFormat::text, "pts:3: expected 3 coordinates, found 2");
  expect_refused("1 2 nan\n", PointFormat::text, "pts:1: field 3: 'nan' is not a number");
}

TEST(PointReader, TruncatedF64NamesThePoint) {
  const std::string two = float64_bytes({{1, 2, 3}, {4, 5, 6}});
  expect_refused(two.substr(0, 23), PointFormat::f64,
                 "pts: point 0 (byte 0): the input ends 23 bytes into this point (f64 input is "
                 "24 bytes per point: x, y, z)");
  expect_refused(two.substr(0, 25), PointFormat::f64,
                 "pts: point 1 (byte 24): the input ends 1 byte into this point (f64 input is "
                 "24 bytes per point: x, y, z)");
  // In a later block.
  expect_refused(two.substr(0, 40), PointFormat::f64,
                 "pts: point 1 (byte 24): the input ends 16 bytes into this point (f64 input is "
                 "24 bytes per point: x, y, z)",
                 1);
}

TEST(PointReader, NpyDataMustMatchTheShape) {
  const Points points = awkward_points(5);
  const std::string file = npy_file(points);  // 128 bytes of header, 120 of data
  ASSERT_EQ(file.size(), 248u);
  for (const std::size_t block : {std::size_t{2}, std::size_t{100}}) {
    expect_refused(file.substr(0, 236), PointFormat::npy,
                   "pts: point 4 (byte 224): the data ends 12 bytes into this point; the "
                   "header's shape declares 5 points",
                   block);
    expect_refused(file.substr(0, 224), PointFormat::npy,
                   "pts: point 4 (byte 224): the data ends before this point; the header's "
                   "shape declares 5 points",
                   block);
    expect_refused(file.substr(0, 128), PointFormat::npy,
                   "pts: point 0 (byte 128): the data ends before this point; the header's "
                   "shape declares 5 points",
                   block);
    expect_refused(file + "x", PointFormat::npy,
                   "pts: byte 248: data continues after the 5 points the header's shape "
                   "declares",
                   block);
  }
  expect_refused(npy_file({}) + std::string(24, '\0'), PointFormat::npy,
                 "pts: byte 128: data continues after the 0 points the header's shape declares");
  // A header whose length runs past the end of the file.
  expect_refused(npy_header(npy_points_dict(5), 2).substr(0, 100), PointFormat::npy,
                 "pts: header: the header is 128 bytes long but the file ends at byte 100");
  expect_refused(file.substr(0, 7), PointFormat::npy,
                 "pts: header: the file ends within the magic string and version (7 bytes)");
}

TEST(PointReader, NonFiniteCoordinatesNameThePoint) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Points points = awkward_points(20);
  points[17][2] = nan;
  expect_refused(float64_bytes(points), PointFormat::f64,
                 "pts: point 17 (byte 408): z is nan; coordinates must be finite");
  for (const int major : {1, 3}) {
    for (const bool big_endian : {false, true}) {
      expect_refused(npy_file(points, major, big_endian), PointFormat::npy,
                     "pts: point 17 (byte 536): z is nan; coordinates must be finite");
    }
  }
  points[17][2] = 0;
  points[3][0] = -inf;
  expect_refused(float64_bytes(points), PointFormat::f64,
                 "pts: point 3 (byte 72): x is -inf; coordinates must be finite");
  points[3][0] = 0;
  points[19][1] = inf;
  expect_refused(npy_file(points, 2, true), PointFormat::npy,
                 "pts: point 19 (byte 584): y is inf; coordinates must be finite", 3);
}

TEST(PointReader, BlocksBeforeAnErrorAreReturned) {
  Points points = awkward_points(10);
  points[8][1] = std::numeric_limits<double>::quiet_NaN();
  std::istringstream in(npy_file(points));
  PointReader reader(in, "pts", PointFormat::npy);
  EXPECT_EQ(reader.read_block(4).size(), 4u);
  EXPECT_EQ(reader.read_block(4).size(), 4u);
  EXPECT_THROW(reader.read_block(4), InputError);
}

}  // namespace
}  // namespace exactgeo::io
