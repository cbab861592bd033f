// libFuzzer target for everything `exactgeo predicate` does with its input: record
// splitting, exact number parsing, case validation and evaluation of orient3d and
// ray-patch on whatever numbers come out. Invariants checked on every input:
//   - no crash, no sanitizer report;
//   - exit code 0 or 2 and nothing else;
//   - on 2: nothing on stdout and exactly one line on stderr;
//   - on 0: one answer per case, nothing on stderr.
//
// Build with clang (see tests/CMakeLists.txt, EXACTGEO_BUILD_FUZZERS) and run e.g.
//   build-fuzz/bin/predicate_input_fuzz -max_total_time=300 tests/fuzz/corpus

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "cli/predicate_command.hpp"

namespace {

void check(bool condition) {
  if (!condition) std::abort();
}

void run_one(exactgeo::cli::PredicateKind kind, const std::string& input) {
  exactgeo::cli::PredicateOptions options;
  options.kind = kind;
  std::istringstream in(input);
  std::ostringstream out, err;
  const auto code = exactgeo::cli::run_predicate(options, in, "<fuzz>", out, err);
  if (code == exactgeo::cli::ExitCode::success) {
    check(err.str().empty());
  } else {
    check(code == exactgeo::cli::ExitCode::input_error);
    check(out.str().empty());
    const std::string e = err.str();
    check(std::count(e.begin(), e.end(), '\n') == 1);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  run_one(exactgeo::cli::PredicateKind::orient3d, input);
  run_one(exactgeo::cli::PredicateKind::ray_patch, input);
  return 0;
}
