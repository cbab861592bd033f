#include "cli/ccd_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <optional>
#include <ostream>
#include <string>

#include "cli/json.hpp"

namespace exactgeo::cli {

using ccd::QueryFile;
using ccd::QueryType;

namespace {

/// The nearest-rank p-quantile of `sorted` (ascending, not empty).
double quantile(const std::vector<double>& sorted, double p) {
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
  return sorted[std::max<std::size_t>(rank, 1) - 1];
}

/// {"queries": n, "median": .., "p99": .., "max": ..} of the times (ns), or null.
void write_distribution(std::ostream& out, std::vector<double> ns) {
  if (ns.empty()) {
    out << "null";
    return;
  }
  std::sort(ns.begin(), ns.end());
  out << "{\"queries\": " << ns.size() << std::fixed << std::setprecision(0)
      << ", \"median\": " << quantile(ns, 0.5) << ", \"p99\": " << quantile(ns, 0.99)
      << ", \"max\": " << ns.back() << std::defaultfloat << "}";
}

/// The per-query times of the files of `type` (all files when none): all of them, and by
/// what decided each query.
void write_query_times(std::ostream& out, const std::vector<QueryFile>& files, const CcdRun& run,
                       std::optional<QueryType> type) {
  std::vector<double> all;
  std::array<std::vector<double>, kDecidedByOrder.size()> by_decider;
  for (std::size_t f = 0; f < files.size(); ++f) {
    if (type && files[f].type != *type) continue;
    for (std::size_t i = 0; i < run.query_ns[f].size(); ++i) {
      all.push_back(run.query_ns[f][i]);
      by_decider[static_cast<std::size_t>(run.results[f][i].decided_by)].push_back(
          run.query_ns[f][i]);
    }
  }
  out << ", \"query_ns\": {\"all\": ";
  write_distribution(out, std::move(all));
  for (const ccd::DecidedBy decided_by : kDecidedByOrder) {
    std::vector<double>& ns = by_decider[static_cast<std::size_t>(decided_by)];
    if (ns.empty()) continue;
    out << ", " << json_string(ccd::to_string(decided_by)) << ": ";
    write_distribution(out, std::move(ns));
  }
  out << "}";
}

/// The counts of `t`; the errors are null without ground truth. The key "stages" (what
/// decided the queries) is the published name.
void write_counts(std::ostream& out, const QueryTally& t, const std::vector<QueryFile>& files,
                  const CcdRun& run, std::optional<QueryType> type) {
  auto errors = [&](std::uint64_t n) {
    return t.with_truth == 0 ? std::string("null") : std::to_string(n);
  };
  out << "\"queries\": " << t.queries << ", \"positives\": " << t.positives
      << ", \"truth_positives\": " << errors(t.truth_positives)
      << ", \"false_positives\": " << errors(t.false_positives)
      << ", \"false_negatives\": " << errors(t.false_negatives)
      << ", \"ns_per_query\": " << std::fixed << std::setprecision(1) << t.ns_per_query()
      << std::defaultfloat << ", \"stages\": {";
  for (std::size_t s = 0; s < kDecidedByOrder.size(); ++s) {
    out << (s ? ", " : "") << json_string(ccd::to_string(kDecidedByOrder[s])) << ": "
        << t.decided_by[static_cast<std::size_t>(kDecidedByOrder[s])];
  }
  out << "}";
  write_query_times(out, files, run, type);
}

}  // namespace

void write_ccd_json(std::ostream& out, const ccd::Options& options,
                    const std::vector<QueryFile>& files, const CcdRun& run) {
  out << "{\"method\": " << json_string(ccd::to_string(options.method))
      << ", \"min_separation\": " << shortest(options.min_separation) << ", ";
  write_counts(out, run.total, files, run, std::nullopt);
  out << ", \"vertex_face\": {";
  write_counts(out, run.vertex_face, files, run, QueryType::vertex_face);
  out << "}, \"edge_edge\": {";
  write_counts(out, run.edge_edge, files, run, QueryType::edge_edge);
  out << "}}\n";
}

}  // namespace exactgeo::cli
