#pragma once

// `exactgeo ccd`: runs CCD queries stored in the public benchmark's CSV format and
// reports results, errors against ground truth and time per query (the command-line contract,
// README.md). The options are cli/ccd_options.hpp, the run cli/ccd_run.hpp, the reports
// cli/ccd_report.hpp.

#include <iosfwd>

#include "cli/ccd_options.hpp"
#include "cli/exit_code.hpp"

namespace exactgeo::cli {

/// Reads every file first (an input error prints nothing on `out`), then runs and reports.
ExitCode run_ccd(const CcdCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace exactgeo::cli
