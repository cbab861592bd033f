#pragma once

// `exactgeo ccd`'s options: what the command line says (registered on CLI11), and the
// library's ccd::Options they make once checked together.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/progress_line.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/files/query_files.hpp"

namespace CLI {
class App;
}

namespace exactgeo::cli {

struct CcdCommandOptions {
  ccd::Options ccd;
  std::optional<ccd::QueryType> type;  ///< overrides what the paths say
  std::string truth;                   ///< a `*_mma_bool.json` for 6-column files, or empty
  std::string per_query;               ///< a CSV file to write, or empty
  int repeat = 1;                      ///< timing passes per file; the fastest is reported
  /// --min-separation as given; checked_ccd_options reads it.
  std::optional<std::string> min_separation;
  bool json = false;
  bool progress_asked = false;  ///< --progress
  /// How progress shows on `err` (the binary sets it: progress_mode(progress_asked, terminal))
  ProgressMode progress = ProgressMode::off;
  std::vector<std::string> paths;
};

/// Registers the subcommand on `app`; `options` must outlive the parse.
CLI::App& add_ccd_command(CLI::App& app, CcdCommandOptions& options);

/// The library's options: options.ccd with --min-separation read (number_option, >= 0), once
/// the options agree with each other (--min-separation > 0 and --toi-width need a method
/// that has them). nullopt, with the reason on `err` ("exactgeo ccd: ..."), otherwise.
std::optional<ccd::Options> checked_ccd_options(const CcdCommandOptions& options,
                                                std::ostream& err);

}  // namespace exactgeo::cli
