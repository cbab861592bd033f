#include "cli/ccd_run.hpp"

#include <algorithm>

#include "cli/seconds.hpp"

namespace exactgeo::cli {

using ccd::QueryFile;
using ccd::QueryRecord;
using ccd::QueryType;

void QueryTally::add(const QueryTally& other) {
  queries += other.queries;
  positives += other.positives;
  with_truth += other.with_truth;
  truth_positives += other.truth_positives;
  false_positives += other.false_positives;
  false_negatives += other.false_negatives;
  seconds += other.seconds;
  for (std::size_t s = 0; s < decided_by.size(); ++s)
    decided_by[s] += other.decided_by[s];
}

double QueryTally::ns_per_query() const {
  return queries == 0 ? 0.0 : seconds * 1e9 / static_cast<double>(queries);
}

namespace {

/// Runs every query of the file `repeat` times; `seconds` is the fastest pass. With
/// `query_ns`, one more pass times each query on its own.
template <class Query, class Make, class Run>
std::vector<ccd::Result> run_timed(const QueryFile& file, Make make, Run run, int repeat,
                                   double& seconds, std::vector<double>* query_ns) {
  std::vector<Query> queries;
  queries.reserve(file.records.size());
  for (const QueryRecord& r : file.records)
    queries.push_back(make(r));
  std::vector<ccd::Result> results(queries.size());
  for (int pass = 0; pass < repeat; ++pass) {
    const Clock::time_point start = Clock::now();
    for (std::size_t i = 0; i < queries.size(); ++i)
      results[i] = run(queries[i]);
    const double elapsed = seconds_since(start);
    seconds = pass == 0 ? elapsed : std::min(seconds, elapsed);
  }
  if (query_ns != nullptr) {
    query_ns->resize(queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Clock::time_point start = Clock::now();
      results[i] = run(queries[i]);
      (*query_ns)[i] = 1e9 * seconds_since(start);
    }
  }
  return results;
}

std::vector<ccd::Result> run_file(const QueryFile& file, const ccd::Options& options, int repeat,
                                  double& seconds, std::vector<double>* query_ns) {
  if (file.type == QueryType::vertex_face) {
    return run_timed<ccd::VertexFaceQuery>(
        file, ccd::vertex_face_query,
        [&](const ccd::VertexFaceQuery& q) { return ccd::vertex_face_ccd(q, options); }, repeat,
        seconds, query_ns);
  }
  return run_timed<ccd::EdgeEdgeQuery>(
      file, ccd::edge_edge_query,
      [&](const ccd::EdgeEdgeQuery& q) { return ccd::edge_edge_ccd(q, options); }, repeat, seconds,
      query_ns);
}

QueryTally tally(const QueryFile& file, const std::vector<ccd::Result>& results, double seconds) {
  QueryTally t;
  t.queries = results.size();
  t.seconds = seconds;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const bool hit = results[i].collision;
    t.positives += hit;
    ++t.decided_by[static_cast<std::size_t>(results[i].decided_by)];
    if (const auto truth = file.records[i].truth) {
      ++t.with_truth;
      t.truth_positives += *truth;
      t.false_positives += hit && !*truth;
      t.false_negatives += !hit && *truth;
    }
  }
  return t;
}

}  // namespace

CcdRun run_queries(const std::vector<QueryFile>& files, const ccd::Options& options, int repeat,
                   bool time_each, ProgressLine& progress) {
  std::size_t total = 0;
  for (const QueryFile& f : files)
    total += f.records.size();
  CcdRun run;
  std::size_t done = 0;
  for (const QueryFile& file : files) {
    double seconds = 0.0;
    run.query_ns.emplace_back();
    run.results.push_back(
        run_file(file, options, repeat, seconds, time_each ? &run.query_ns.back() : nullptr));
    (file.type == QueryType::vertex_face ? run.vertex_face : run.edge_edge)
        .add(tally(file, run.results.back(), seconds));
    done += file.records.size();
    progress.count(done, total);
  }
  run.total.add(run.vertex_face);
  run.total.add(run.edge_edge);
  return run;
}

}  // namespace exactgeo::cli
