#include "cli/threads_option.hpp"

#include <CLI/CLI.hpp>

namespace exactgeo::cli {

void add_threads_option(CLI::App& sub, unsigned& threads) {
  sub.add_option("--threads", threads, "worker threads (default: all hardware threads)")
      ->check(CLI::Range(1u, 1024u));
}

}  // namespace exactgeo::cli
