#include "cli/ccd_command.hpp"

#include <algorithm>
#include <optional>
#include <ostream>
#include <vector>

#include "cli/ccd_report.hpp"
#include "cli/ccd_run.hpp"
#include "cli/output_file.hpp"
#include "cli/progress_line.hpp"
#include "exactgeo/ccd/files/query_files.hpp"
#include "exactgeo/io/input_error.hpp"

namespace exactgeo::cli {

using ccd::QueryFile;
using ccd::QueryRecord;
using io::InputError;

ExitCode run_ccd(const CcdCommandOptions& options, std::ostream& out, std::ostream& err) {
  const std::optional<ccd::Options> checked = checked_ccd_options(options, err);
  if (!checked) return ExitCode::input_error;
  std::vector<QueryFile> files;
  try {
    files = ccd::read_query_files(options.paths, options.type, options.truth);
  } catch (const InputError& e) {
    err << "exactgeo ccd: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  // The files' ground truth is about contact (δ = 0); at a larger δ it does not apply.
  if (checked->min_separation > 0.0) {
    for (QueryFile& f : files) {
      for (QueryRecord& r : f.records)
        r.truth.reset();
    }
  }
  std::size_t total = 0;
  for (const QueryFile& f : files)
    total += f.records.size();
  if (total == 0) {
    // Every file is empty (or blank lines only): name them, the first few if many.
    err << "exactgeo ccd: no queries in ";
    if (files.size() == 1) {
      err << files.front().path;
    } else {
      err << "any of the " << files.size() << " files read (";
      constexpr std::size_t kNamed = 3;
      for (std::size_t k = 0; k < std::min(files.size(), kNamed); ++k)
        err << (k > 0 ? ", " : "") << files[k].path;
      err << (files.size() > kNamed ? ", ...)" : ")");
    }
    err << ": a query is 8 lines of x_num,x_den,y_num,y_den,z_num,z_den[,truth]\n";
    return ExitCode::input_error;
  }

  // The CSV file is reserved before the run, so an unwritable path fails at once; it is
  // written whole or not at all.
  std::optional<OutputFile> per_query_file;
  try {
    if (!options.per_query.empty()) per_query_file.emplace(options.per_query);
  } catch (const OutputFileError& e) {
    err << "exactgeo ccd: --per-query: " << e.what() << "\n";
    return ExitCode::input_error;
  }

  const bool time_each = options.json || !options.per_query.empty();
  ProgressLine progress(err, options.progress, "queries");
  const CcdRun run = run_queries(files, *checked, options.repeat, time_each, progress);
  progress.clear();
  if (per_query_file) {
    try {
      per_query_file->commit(ccd_per_query_csv(files, run));
    } catch (const OutputFileError& e) {
      err << "exactgeo ccd: --per-query: " << e.what() << "\n";
      return ExitCode::input_error;
    }
  }
  if (options.json) {
    write_ccd_json(out, *checked, files, run);
  } else {
    write_ccd_table(out, *checked, run);
  }
  return run.total.false_negatives > 0 ? ExitCode::found : ExitCode::success;
}

}  // namespace exactgeo::cli
