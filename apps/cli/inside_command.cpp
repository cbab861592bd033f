#include "cli/inside_command.hpp"

#include <CLI/CLI.hpp>

#include <array>
#include <chrono>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/numbers.hpp"
#include "exactgeo/mesh/load.hpp"

namespace exactgeo::cli {

using io::InputError;
using io::RecordReader;
using mesh::load_mesh;
using mesh::LoadedMesh;
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Points per block: large enough to keep every thread busy, small enough that memory
/// stays flat (about 2 MB of points and labels).
constexpr std::size_t kBlockPoints = std::size_t{1} << 16;

/// Reads up to kBlockPoints points; an empty block means the input is exhausted.
void read_block(RecordReader& reader, std::vector<Point3>& block) {
  block.clear();
  while (block.size() < kBlockPoints) {
    const auto record = reader.next();
    if (!record) return;
    if (record->size() != 3) {
      throw InputError(reader.source(), reader.line_number(),
                       "expected 3 coordinates, found " + std::to_string(record->size()));
    }
    block.push_back({(*record)[0], (*record)[1], (*record)[2]});
  }
}

struct Tally {
  std::size_t points = 0;
  std::array<std::size_t, 3> by_location{};  // indexed by inside::Location
  double seconds = 0.0;
};

}  // namespace

ExitCode run_inside(const InsideCommandOptions& options, std::istream& in,
                    const std::string& points_source, std::ostream& out, std::ostream& err) {
  std::optional<inside::Classifier> classifier;
  double build_seconds = 0.0;
  try {
    LoadedMesh loaded = load_mesh(options.mesh, {options.weld, options.split_polygons});
    const Clock::time_point start = Clock::now();
    inside::ClassifierOptions classifier_options;
    classifier_options.allow_non_manifold = options.allow_non_manifold;
    classifier.emplace(std::move(loaded.mesh), classifier_options);
    build_seconds = seconds_since(start);
  } catch (const InputError& e) {
    err << "exactgeo inside: " << e.what() << "\n";
    return ExitCode::input_error;
  } catch (const std::invalid_argument& e) {
    err << "exactgeo inside: " << options.mesh << ": " << e.what() << "\n";
    return ExitCode::input_error;
  } catch (const std::exception& e) {  // Embree failing, or memory running out
    err << "exactgeo inside: " << options.mesh
        << ": cannot build the search structure: " << e.what() << "\n";
    return ExitCode::input_error;
  }

  Tally tally;
  RecordReader reader(in, points_source);
  std::vector<Point3> block;
  std::vector<inside::Location> locations;
  std::string text;
  try {
    for (read_block(reader, block); !block.empty(); read_block(reader, block)) {
      locations.resize(block.size());
      const Clock::time_point start = Clock::now();
      inside::classify_batch(*classifier, block, locations, options.arithmetic, options.threads);
      tally.seconds += seconds_since(start);
      tally.points += block.size();
      text.clear();
      for (const inside::Location l : locations) {
        ++tally.by_location[static_cast<std::size_t>(l)];
        if (!options.json) text.append(to_string(l)).push_back('\n');
      }
      out << text;
      if (options.progress) err << "\r" << tally.points << " points" << std::flush;
    }
  } catch (const InputError& e) {
    out << std::flush;
    if (options.progress) err << "\r\033[K";
    err << "exactgeo inside: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  if (options.progress) err << "\r\033[K" << std::flush;

  if (options.json) {
    const auto count = [&](inside::Location l) {
      return tally.by_location[static_cast<std::size_t>(l)];
    };
    out << "{\"points\": " << tally.points << ", \"inside\": " << count(inside::Location::inside)
        << ", \"outside\": " << count(inside::Location::outside)
        << ", \"boundary\": " << count(inside::Location::boundary) << ", \"method\": \""
        << to_string(options.arithmetic) << "\""
        << ", \"build_seconds\": " << build_seconds << ", \"seconds\": " << tally.seconds << "}\n";
  }
  out << std::flush;
  return ExitCode::success;
}

CLI::App& add_inside_command(CLI::App& app, InsideCommandOptions& options) {
  CLI::App* sub = app.add_subcommand(
      "inside",
      "Classify points against a closed quad/triangle mesh, exactly: one word per point "
      "(inside, outside or boundary), in input order. POINTS has three numbers per line "
      "(decimal or hexfloat, separated by spaces and/or commas; '#' comments).");
  sub->add_option("mesh", options.mesh, "OBJ, OFF or PLY (exact), or any format assimp reads")
      ->required();
  sub->add_option("points", options.points, "points file, or - for standard input (default)");
  sub->add_option_function<std::string>(
         "--method",
         [&options](const std::string& m) { options.arithmetic = *parse_arithmetic(m); },
         "exact (default) or double (the same traversal in plain doubles: fast, not exact)")
      ->check(CLI::IsMember({"exact", "double"}));
  sub->add_option("--threads", options.threads, "worker threads (default: all hardware threads)")
      ->check(CLI::Range(1u, 1024u));
  sub->add_flag("--json", options.json,
                "print one JSON object (counts, build and classification seconds) instead of "
                "the labels");
  sub->add_flag("--weld", options.weld, "merge vertices with exactly equal coordinates");
  sub->add_flag("--split-polygons", options.split_polygons,
                "split faces with more than four corners into triangle fans");
  sub->add_flag("--allow-non-manifold", options.allow_non_manifold,
                "accept edges shared by 4, 6, ... faces (parity is still defined)");
  return *sub;
}

}  // namespace exactgeo::cli
