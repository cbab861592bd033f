#pragma once

// --progress, the same on every subcommand that shows progress (cli/progress_line.hpp):
// progress lines on standard error also when it is not a terminal (a log, a notebook).

namespace CLI {
class App;
}

namespace exactgeo::cli {

/// Registers `--progress` on `sub`; `asked` must outlive the parse. The binary turns it
/// into a ProgressMode with progress_mode(asked, whether standard error is a terminal).
void add_progress_flag(CLI::App& sub, bool& asked);

}  // namespace exactgeo::cli
