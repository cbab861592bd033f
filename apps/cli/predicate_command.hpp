#pragma once

// `exactgeo predicate orient3d|ray-patch`: exact predicates on a batch of cases, one per
// line of text, one answer per line (the command-line contract, README.md).

#include <iosfwd>
#include <string>

#include "cli/exit_code.hpp"
#include "exactgeo/predicates/arithmetic.hpp"

namespace CLI {
class App;
}

namespace exactgeo::cli {

enum class PredicateKind { orient3d, ray_patch };

struct PredicateOptions {
  PredicateKind kind = PredicateKind::orient3d;
  Arithmetic arithmetic = Arithmetic::exact;
  bool json = false;
  std::string input = "-";  ///< a file, or "-" for standard input
};

/// Evaluates every case of `in` (named `source` in messages). Writes the answers to `out`
/// only when the whole input is valid; otherwise writes nothing there, the reason to
/// `err`, and returns ExitCode::input_error.
ExitCode run_predicate(const PredicateOptions& options, std::istream& in, const std::string& source,
                       std::ostream& out, std::ostream& err);

/// Registers the subcommand on `app`; `options` must outlive the parse.
CLI::App& add_predicate_command(CLI::App& app, PredicateOptions& options);

}  // namespace exactgeo::cli
