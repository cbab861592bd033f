#include "cli/predicate_command.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>
#include <vector>

#include "cli/json.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/numbers.hpp"
#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/orient3d.hpp"

namespace exactgeo::cli {

using io::InputError;
using io::RecordReader;

namespace {

Point3 point_at(const std::vector<double>& x, std::size_t first) {
  return {x[first], x[first + 1], x[first + 2]};
}

std::size_t numbers_per_case(PredicateKind kind) {
  return kind == PredicateKind::orient3d ? 12 : 18;
}

std::string_view name_of(PredicateKind kind) {
  return kind == PredicateKind::orient3d ? "orient3d" : "ray-patch";
}

/// The answer to one case, as printed.
std::string evaluate(const PredicateOptions& options, const std::vector<double>& x,
                     const RecordReader& reader) {
  if (options.kind == PredicateKind::orient3d) {
    const Sign s = orient3d(point_at(x, 0), point_at(x, 3), point_at(x, 6), point_at(x, 9),
                            options.arithmetic);
    return std::to_string(to_int(s));
  }
  const Vector3 direction = point_at(x, 3);
  if (direction[0] == 0 && direction[1] == 0 && direction[2] == 0) {
    throw InputError(reader.source(), reader.line_number(), "the ray direction is zero");
  }
  const BilinearPatch patch{point_at(x, 6), point_at(x, 9), point_at(x, 12), point_at(x, 15)};
  return std::string(
      to_string(ray_patch_parity(point_at(x, 0), direction, patch, options.arithmetic)));
}

}  // namespace

ExitCode run_predicate(const PredicateOptions& options, std::istream& in, const std::string& source,
                       std::ostream& out, std::ostream& err) {
  std::vector<std::string> answers;
  try {
    RecordReader reader(in, source);
    const std::size_t expected = numbers_per_case(options.kind);
    while (const auto numbers = reader.next()) {
      if (numbers->size() != expected) {
        throw InputError(source, reader.line_number(),
                         "expected " + std::to_string(expected) + " numbers for " +
                             std::string(name_of(options.kind)) + ", found " +
                             std::to_string(numbers->size()));
      }
      answers.push_back(evaluate(options, *numbers, reader));
    }
  } catch (const InputError& e) {
    err << "exactgeo predicate: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  std::ostringstream text;
  if (options.json) {
    text << "{\"predicate\": " << json_string(name_of(options.kind))
         << ", \"arithmetic\": " << json_string(to_string(options.arithmetic))
         << ", \"count\": " << answers.size() << ", \"results\": [";
    for (std::size_t i = 0; i < answers.size(); ++i) {
      text << (i ? ", " : "")
           << (options.kind == PredicateKind::orient3d ? answers[i] : json_string(answers[i]));
    }
    text << "]}\n";
  } else {
    for (const std::string& a : answers)
      text << a << "\n";
  }
  out << text.str();
  out.flush();
  return ExitCode::success;
}

CLI::App& add_predicate_command(CLI::App& app, PredicateOptions& options) {
  CLI::App* sub = app.add_subcommand(
      "predicate",
      "Evaluate an exact predicate on cases read one per line (decimal or hexfloat numbers "
      "separated by spaces and/or commas; blank lines and # comments skipped).\n"
      "  orient3d : 12 numbers a b c d; prints 1, 0 or -1, the sign of det[b-a, c-a, d-a]\n"
      "  ray-patch: 18 numbers origin direction p00 p10 p11 p01; prints odd, even, on\n"
      "             (origin on the patch) or degenerate (ask again with another direction)");
  sub->add_option_function<std::string>(
         "predicate",
         [&options](const std::string& name) {
           options.kind = name == "orient3d" ? PredicateKind::orient3d : PredicateKind::ray_patch;
         },
         "orient3d or ray-patch")
      ->required()
      ->check(CLI::IsMember({"orient3d", "ray-patch"}));
  sub->add_option("input", options.input, "file of cases, or - for standard input (default)");
  sub->add_option_function<std::string>(
         "--arithmetic",
         [&options](const std::string& name) { options.arithmetic = *parse_arithmetic(name); },
         "exact (default), double (plain double evaluation of the same formulas: fast, not "
         "exact) or rational (GMP throughout: slow reference)")
      ->check(CLI::IsMember({"exact", "double", "rational"}));
  sub->add_flag("--json", options.json, "print one JSON object instead of one answer per line");
  return *sub;
}

}  // namespace exactgeo::cli
