#pragma once

// `exactgeo ccd`: runs CCD queries stored in the public benchmark's CSV format and
// reports results, errors against ground truth and time per query (the command-line contract,
// README.md).

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/exit_code.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/files/query_files.hpp"

namespace CLI {
class App;
}

namespace exactgeo::cli {

struct CcdCommandOptions {
  ccd::Options ccd;
  std::optional<ccd::QueryType> type;         ///< overrides what the paths say
  std::string truth;                          ///< a `*_mma_bool.json` for 6-column files, or empty
  std::string per_query;                      ///< a CSV file to write, or empty
  int repeat = 1;                             ///< timing passes per file; the fastest is reported
  std::optional<std::string> min_separation;  ///< --min-separation as given (run_ccd checks it)
  bool json = false;
  bool progress = false;  ///< a progress line on `err` (the binary sets it for a terminal)
  std::vector<std::string> paths;
};

/// Reads every file first (an input error prints nothing on `out`), then runs and reports.
ExitCode run_ccd(const CcdCommandOptions& options, std::ostream& out, std::ostream& err);

/// Registers the subcommand on `app`; `options` must outlive the parse.
CLI::App& add_ccd_command(CLI::App& app, CcdCommandOptions& options);

}  // namespace exactgeo::cli
