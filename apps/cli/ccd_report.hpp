#pragma once

// `exactgeo ccd`'s reports of a run (cli/ccd_run.hpp), one format per file:
//   ccd_report_table.cpp  the table printed by default
//   ccd_report_json.cpp   --json: one object, with the distribution of each query's time
//   ccd_report_csv.cpp    --per-query: one CSV line per query

#include <iosfwd>
#include <string>
#include <vector>

#include "cli/ccd_run.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/files/query_files.hpp"

namespace exactgeo::cli {

/// The method (and the separation, when not 0), then queries, positives, errors against
/// ground truth ("-" without it) and ns per query for each type and in total, then how
/// many queries each DecidedBy decided.
void write_ccd_table(std::ostream& out, const ccd::Options& options, const CcdRun& run);

/// One JSON object: the method, the separation, the counts in total and per type, each
/// with the median, 99th percentile and maximum of the queries' own times, in all and by
/// what decided them. Precondition: `run` timed each query of `files`.
void write_ccd_json(std::ostream& out, const ccd::Options& options,
                    const std::vector<ccd::QueryFile>& files, const CcdRun& run);

/// path,index,type,result,truth,decided_by,ns,toi_start,toi_end: one line per query, in
/// file order. Precondition: `run` timed each query of `files`.
std::string ccd_per_query_csv(const std::vector<ccd::QueryFile>& files, const CcdRun& run);

}  // namespace exactgeo::cli
