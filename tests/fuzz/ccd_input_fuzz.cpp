// libFuzzer target for the CCD benchmark readers behind `exactgeo ccd`: the query CSV
// (arbitrary-size integers, exact num/den, 6 or 7 columns, 8 rows per query) and the
// ground-truth JSON array. Invariants on every input:
//   - no crash, no sanitizer report;
//   - either an InputError with a message naming "<fuzz>", or records whose every
//     coordinate is a finite double, and then every query runs through the exact method
//     (and agrees with parity where parity reports a collision).
//
// Build with clang (EXACTGEO_BUILD_FUZZERS) and run e.g.
//   build-fuzz/bin/ccd_input_fuzz -max_total_time=300

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/files/query_files.hpp"
#include "exactgeo/ccd/root_parity.hpp"
#include "exactgeo/io/input_error.hpp"

namespace {

void check(bool condition) {
  if (!condition) std::abort();
}

void run_queries(const std::string& text) {
  std::istringstream in(text);
  std::vector<exactgeo::ccd::QueryRecord> records;
  try {
    records = exactgeo::ccd::read_query_records(in, "<fuzz>");
  } catch (const exactgeo::io::InputError& e) {
    check(std::string(e.what()).find("<fuzz>") != std::string::npos);
    return;
  }
  for (const auto& r : records) {
    for (const auto& p : r.points) {
      for (const double x : p)
        check(std::isfinite(x));
    }
    exactgeo::ccd::Options options;
    options.max_depth = 12;  // keep each input fast; depth changes no parity answer
    const auto vf = exactgeo::ccd::vertex_face_query(r);
    if (exactgeo::ccd::vertex_face_root_parity(vf).collision()) {
      check(exactgeo::ccd::vertex_face_ccd(vf, options).collision);
    }
    const auto ee = exactgeo::ccd::edge_edge_query(r);
    if (exactgeo::ccd::edge_edge_root_parity(ee).collision()) {
      check(exactgeo::ccd::edge_edge_ccd(ee, options).collision);
    }
  }
}

void run_truth(const std::string& text) {
  std::istringstream in(text);
  try {
    (void)exactgeo::ccd::read_truth_array(in, "<fuzz>");
  } catch (const exactgeo::io::InputError& e) {
    check(std::string(e.what()).find("<fuzz>") != std::string::npos);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] % 2 == 0) {
    run_queries(text);
  } else {
    run_truth(text);
  }
  return 0;
}
