#include "cli/progress_option.hpp"

#include <CLI/CLI.hpp>

namespace exactgeo::cli {

void add_progress_flag(CLI::App& sub, bool& asked) {
  sub.add_flag("--progress", asked,
               "write progress to standard error also when it is not a terminal (a log, a "
               "notebook): each stage and, at most once a second, the count so far, a line "
               "each (on a terminal one line is kept up to date, with or without this flag)");
}

}  // namespace exactgeo::cli
