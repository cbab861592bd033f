// The .npy header: what np.save writes is read in every version and byte order; the dict
// is read tolerantly of layout; everything else is refused naming the file and the header.

#include "exactgeo/io/npy_header.hpp"

#include <gtest/gtest.h>

#include <string>

#include "exactgeo/io/input_error.hpp"
#include "support/npy_bytes.hpp"

namespace exactgeo::io {
namespace {

using namespace std::string_literals;
using testing::npy_header;
using testing::npy_points_dict;

/// The message parse_npy_header throws for `bytes` ("" if it throws none).
std::string refusal(const std::string& bytes) {
  try {
    parse_npy_header(bytes, "p.npy");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Expects a refusal that names the file and the header and contains `what`.
void expect_refused(const std::string& bytes, const std::string& what) {
  const std::string message = refusal(bytes);
  EXPECT_EQ(message.rfind("p.npy: header: ", 0), 0u) << message;
  EXPECT_NE(message.find(what), std::string::npos) << "'" << message << "' lacks '" << what << "'";
}

TEST(NpyHeader, ReadsWhatNumpyWrites) {
  // np.lib.format.write_array(f, np.zeros((1000, 3), dtype), version=...), verbatim.
  const std::string pad(55, ' ');
  const std::string v1 = "\x93NUMPY\x01\x00v\x00"s +
                         "{'descr': '<f8', 'fortran_order': False, 'shape': (1000, 3), }" + pad +
                         "\n";
  const std::string v2 = "\x93NUMPY\x02\x00t\x00\x00\x00"s +
                         "{'descr': '>f8', 'fortran_order': False, 'shape': (1000, 3), }" +
                         pad.substr(2) + "\n";
  ASSERT_EQ(v1.size(), 128u);
  ASSERT_EQ(v2.size(), 128u);
  for (const std::string& header : {v1, v2, "\x93NUMPY\x03"s + v2.substr(7)}) {
    EXPECT_EQ(npy_header_size(header.substr(0, kNpyPreambleBytes), "p.npy"), 128u);
    const NpyPoints points = parse_npy_header(header + "data after the header", "p.npy");
    EXPECT_EQ(points.points, 1000u);
    EXPECT_EQ(points.data_offset, 128u);
    EXPECT_EQ(points.big_endian, header[6] != '\x01');  // v1 is '<f8', v2 and v3 '>f8'
  }
}

TEST(NpyHeader, EmptyArrayAndLargeCounts) {
  EXPECT_EQ(parse_npy_header(npy_header(npy_points_dict(0)), "p.npy").points, 0u);
  const std::string big = npy_header(
      "{'descr': '<f8', 'fortran_order': False, "
      "'shape': (768614336404564645, 3), }");
  EXPECT_EQ(parse_npy_header(big, "p.npy").points, 768614336404564645u);
}

TEST(NpyHeader, DictLayoutIsFree) {
  for (const char* dict : {
           "{'shape': (5, 3), 'fortran_order': False, 'descr': '<f8'}",
           "{\"descr\": \"<f8\", \"fortran_order\": False, \"shape\": (5, 3)}",
           "  {  'descr' :'<f8' ,'fortran_order':False,'shape':( 5 ,3 , ) , }  ",
           "{'descr': '<f8',\n 'fortran_order': False,\n\t'shape': (5L, 3L)}",
       }) {
    const NpyPoints points = parse_npy_header(npy_header(dict, 2), "p.npy");
    EXPECT_EQ(points.points, 5u) << dict;
    EXPECT_FALSE(points.big_endian) << dict;
  }
}

TEST(NpyHeader, RefusesBadPreambles) {
  const std::string good = npy_header(npy_points_dict(5));
  expect_refused("", "the input is empty");
  expect_refused("PK\x03\x04 a zip file", "not an .npy file");
  expect_refused("\x93NUM", "ends within the magic string");
  expect_refused("\x93NUMPY\x04\x00rest"s, "format version 4.0; accepted: 1.0, 2.0, 3.0");
  expect_refused("\x93NUMPY\x01\x01rest"s, "format version 1.1");
  expect_refused("\x93NUMPY\x01\x00v"s, "ends within the header length");
  expect_refused("\x93NUMPY\x02\x00v\x00\x00"s, "ends within the header length");
  expect_refused(good.substr(0, 50), "the header is 128 bytes long but the file ends at byte 50");
  expect_refused("\x93NUMPY\x02\x00\xff\xff\xff\xff"s + good.substr(10),
                 "the header length 4294967295 is larger than 65536 bytes");
  EXPECT_THROW(npy_header_size("\x93NUMPY\x03\x00\x01\x00\x01\x00"s, "p.npy"), InputError);
}

TEST(NpyHeader, RefusesMalformedDicts) {
  const auto refused = [](const std::string& dict, const std::string& what) {
    expect_refused(npy_header(dict), what);
  };
  refused("", "the header is not a dict (at byte 64)");
  refused("['descr', '<f8']", "the header is not a dict");
  refused("{'descr': '<f8', 'fortran_order': False}", "the dict lacks 'shape'");
  refused("{'fortran_order': False, 'shape': (5, 3)}", "the dict lacks 'descr'");
  refused("{'descr': '<f8', 'shape': (5, 3)}", "the dict lacks 'fortran_order'");
  refused("{'descr': '<f8', 'descr': '<f8', 'fortran_order': False, 'shape': (5, 3)}",
          "'descr' appears twice (at byte 27)");
  refused("{'descr': '<f8', 'fortran_order': False, 'shape': (5, 3), 'x': 1}",
          "unexpected key 'x'");
  refused("{'descr' '<f8', 'fortran_order': False, 'shape': (5, 3)}",
          "expected ':' after a key (at byte 19)");
  refused("{'descr': '<f8', 'fortran_order': False, 'shape': (5, 3)", "expected ',' or '}'");
  refused("{'descr': '<f8' 'fortran_order': False, 'shape': (5, 3)}", "expected ',' or '}'");
  refused("{'descr': '<f8', 'fortran_order': false, 'shape': (5, 3)}",
          "fortran_order is not True or False");
  refused("{'descr': '<f8', 'fortran_order': False, 'shape': [5, 3]}", "shape is not a tuple");
  refused("{'descr': '<f8', 'fortran_order': False, 'shape': (5)}", "shape is not a tuple");
  refused("{'descr': '<f8', 'fortran_order': False, 'shape': (-5, 3)}",
          "a shape entry is not a non-negative integer");
  refused("{'descr': '<f8', 'fortran_order': False, 'shape': (5 3)}", "expected ',' or ')'");
  refused("{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999999999999, 3)}",
          "a shape entry is too large");
  refused("{'descr': '<f8', 'fortran_order': False, 'shape': (5, 3)} x",
          "unexpected text after the dict");
  refused("{'descr': 8, 'fortran_order': False, 'shape': (5, 3)}", "descr is not a string");
  refused("{'descr': '<f8\\n', 'fortran_order': False, 'shape': (5, 3)}", "backslash");
  refused("{'descr': '<f8", "a string is not closed");
}

TEST(NpyHeader, RefusesOtherArraysSayingWhatIsAccepted) {
  const auto refused = [](const std::string& descr, const std::string& fortran,
                          const std::string& shape, const std::string& what) {
    expect_refused(npy_header("{'descr': " + descr + ", 'fortran_order': " + fortran +
                              ", 'shape': " + shape + ", }"),
                   what);
  };
  const std::string accepted = "accepted: '<f8' or '>f8' (float64";
  refused("'<f4'", "False", "(5, 3)", "descr is '<f4'; " + accepted);
  refused("'<i8'", "False", "(5, 3)", "descr is '<i8'; " + accepted);
  refused("'|O'", "False", "(5, 3)", "descr is '|O'; " + accepted);
  refused("'=f8'", "False", "(5, 3)", "descr is '=f8'; " + accepted);
  refused("[('x', '<f8'), ('y', '<f8'), ('z', '<f8')]", "False", "(5,)",
          "descr is a list of fields (a structured array)");
  refused("'<f8'", "True", "(5, 3)", "np.ascontiguousarray");
  refused("'<f8'", "False", "(5,)", "shape is (5,); accepted: (n, 3)");
  refused("'<f8'", "False", "(15,)", "shape is (15,)");
  refused("'<f8'", "False", "()", "shape is ()");
  refused("'<f8'", "False", "(5, 4)", "shape is (5, 4)");
  refused("'<f8'", "False", "(3, 5)", "shape is (3, 5)");
  refused("'<f8'", "False", "(5, 3, 1)", "shape is (5, 3, 1)");
  // n * 24 bytes past the largest offset.
  refused("'<f8'", "False", "(768614336404564646, 3)", "too many points");
}

}  // namespace
}  // namespace exactgeo::io
