#pragma once

// `exactgeo ccd`'s run: every query of the files, timed, with what decided each and the
// counts against ground truth, per query type and in total. Nothing here prints; the
// reports are cli/ccd_report.hpp.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cli/progress_line.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/files/query_files.hpp"

namespace exactgeo::cli {

/// Everything that can decide a query, in the order of the reports. A tally indexes by a
/// DecidedBy's value: one slot for each.
inline constexpr std::array kDecidedByOrder{
    ccd::DecidedBy::culled,      ccd::DecidedBy::parity,           ccd::DecidedBy::polynomials,
    ccd::DecidedBy::subdivision, ccd::DecidedBy::depth_limit,      ccd::DecidedBy::cubic,
    ccd::DecidedBy::separation,  ccd::DecidedBy::separation_roots, ccd::DecidedBy::box_test};
static_assert(static_cast<std::size_t>(ccd::DecidedBy::box_test) + 1 == kDecidedByOrder.size());

/// Counts for one query type, or for all.
struct QueryTally {
  std::uint64_t queries = 0;
  std::uint64_t positives = 0;
  std::uint64_t with_truth = 0;  ///< queries with ground truth; the errors count among them
  std::uint64_t truth_positives = 0;
  std::uint64_t false_positives = 0;
  std::uint64_t false_negatives = 0;
  double seconds = 0.0;  ///< the fastest pass over each file, summed
  /// Queries by what decided them, indexed by the DecidedBy value.
  std::array<std::uint64_t, kDecidedByOrder.size()> decided_by{};

  void add(const QueryTally& other);
  double ns_per_query() const;
};

/// What one run produced, file by file in the order of the files run.
struct CcdRun {
  std::vector<std::vector<ccd::Result>> results;  ///< per file, every query's result
  /// Per file, every query's own time in ns; empty vectors when each query was not timed.
  std::vector<std::vector<double>> query_ns;
  QueryTally vertex_face;
  QueryTally edge_edge;
  QueryTally total;  ///< both types
};

/// Runs every query of `files` with `options`. Each file is run `repeat` times and its time
/// is the fastest pass (on a shared machine the least disturbed one); the answers do not
/// depend on the pass. With `time_each`, one more pass times each query on its own (each
/// time then includes one reading of the clock, small against a query but not nothing),
/// for the distribution of query times. `progress` counts the queries done after each file.
CcdRun run_queries(const std::vector<ccd::QueryFile>& files, const ccd::Options& options,
                   int repeat, bool time_each, ProgressLine& progress);

}  // namespace exactgeo::cli
