#pragma once

// `--threads N`, the same on every subcommand that runs on several threads: 1 to 1024
// worker threads; left unset (0), one per hardware thread.

namespace CLI {
class App;
}

namespace exactgeo::cli {

/// Registers `--threads` on `sub`; `threads` (0 until given: all hardware threads) must
/// outlive the parse.
void add_threads_option(CLI::App& sub, unsigned& threads);

}  // namespace exactgeo::cli
