// exactgeo: the command-line tool. Subcommands live in cli/; this file wires them up and
// maps errors to exit codes (0 success, 1 found, 2 usage or input error).

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <fstream>
#include <iostream>

#include "cli/ccd_command.hpp"
#include "cli/exit_code.hpp"
#include "cli/predicate_command.hpp"
#include "exactgeo/version.hpp"

namespace {

using exactgeo::cli::ExitCode;

int run_predicate_from(const exactgeo::cli::PredicateOptions& options) {
  if (options.input == "-") {
    return to_int(exactgeo::cli::run_predicate(options, std::cin, "<stdin>", std::cout, std::cerr));
  }
  std::ifstream file(options.input, std::ios::binary);
  if (!file) {
    std::cerr << "exactgeo predicate: cannot open '" << options.input << "'\n";
    return to_int(ExitCode::input_error);
  }
  return to_int(exactgeo::cli::run_predicate(options, file, options.input, std::cout, std::cerr));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "exactgeo: geometrically exact predicates, continuous collision detection and "
      "point-in-volume classification.",
      "exactgeo"};
  app.set_version_flag("--version", std::string("exactgeo ") + exactgeo::kVersion);
  app.require_subcommand(1);

  exactgeo::cli::PredicateOptions predicate;
  CLI::App& predicate_command = exactgeo::cli::add_predicate_command(app, predicate);
  exactgeo::cli::CcdCommandOptions ccd;
  CLI::App& ccd_command = exactgeo::cli::add_ccd_command(app, ccd);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, version or the error
    return code == 0 ? 0 : to_int(ExitCode::input_error);
  }
  if (predicate_command.parsed()) return run_predicate_from(predicate);
  if (ccd_command.parsed()) {
    ccd.progress = isatty(STDERR_FILENO) != 0;
    return to_int(exactgeo::cli::run_ccd(ccd, std::cout, std::cerr));
  }
  return to_int(ExitCode::input_error);
}
