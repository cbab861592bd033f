// exactgeo: the command-line tool. Subcommands live in cli/; this file wires them up and
// maps errors to exit codes (0 success, 1 found, 2 usage or input error).

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <fstream>
#include <iostream>

#include "cli/ccd_command.hpp"
#include "cli/ccd_mesh_command.hpp"
#include "cli/exit_code.hpp"
#include "cli/info_command.hpp"
#include "cli/inside_batch.hpp"
#include "cli/inside_command.hpp"
#include "cli/predicate_command.hpp"
#include "cli/progress_line.hpp"
#include "exactgeo/version.hpp"

namespace {

using exactgeo::cli::ExitCode;

/// Runs `run(stream, source name)` on standard input for "-", else on the named file.
template <class Run>
int with_input(const std::string& path, const char* command, Run run) {
  if (path == "-") return to_int(run(std::cin, "<stdin>"));
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    std::cerr << "exactgeo " << command << ": cannot open '" << path << "'\n";
    return to_int(ExitCode::input_error);
  }
  return to_int(run(file, path));
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
  exactgeo::cli::CcdMeshOptions ccd_mesh;
  CLI::App& ccd_mesh_command = exactgeo::cli::add_ccd_mesh_command(app, ccd_mesh);
  exactgeo::cli::InfoOptions info;
  CLI::App& info_command = exactgeo::cli::add_info_command(app, info);
  exactgeo::cli::InsideCommandOptions inside;
  CLI::App& inside_command = exactgeo::cli::add_inside_command(app, inside);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // help or version
    // The error, named by the subcommand it belongs to.
    std::string command = "exactgeo";
    for (const CLI::App* sub : app.get_subcommands())
      command += " " + sub->get_name();
    std::cerr << command << ": " << e.what() << "\nRun '" << command
              << " --help' for more information.\n";
    return to_int(ExitCode::input_error);
  }
  if (predicate_command.parsed()) {
    return with_input(
        predicate.input, "predicate", [&](std::istream& in, const std::string& source) {
          return exactgeo::cli::run_predicate(predicate, in, source, std::cout, std::cerr);
        });
  }
  if (ccd_command.parsed()) {
    ccd.progress = exactgeo::cli::progress_mode(ccd.progress_asked, isatty(STDERR_FILENO) != 0);
    return to_int(exactgeo::cli::run_ccd(ccd, std::cout, std::cerr));
  }
  if (ccd_mesh_command.parsed()) {
    return to_int(exactgeo::cli::run_ccd_mesh(ccd_mesh, std::cout, std::cerr));
  }
  if (inside_command.parsed()) {
    inside.progress =
        exactgeo::cli::progress_mode(inside.progress_asked, isatty(STDERR_FILENO) != 0);
    if (!inside.output_dir.empty()) {
      return to_int(exactgeo::cli::run_inside_batch(inside, std::cout, std::cerr));
    }
    return with_input(inside.points, "inside", [&](std::istream& in, const std::string& source) {
      return exactgeo::cli::run_inside(inside, in, source, std::cout, std::cerr);
    });
  }
  if (info_command.parsed()) return to_int(exactgeo::cli::run_info(info, std::cout, std::cerr));
  return to_int(ExitCode::input_error);
}
