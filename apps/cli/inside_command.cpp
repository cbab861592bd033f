#include "cli/inside_command.hpp"

#include <CLI/CLI.hpp>

#include <array>
#include <chrono>
#include <istream>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/mesh_format_option.hpp"
#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/float_ray_parity.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/point_reader.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/mesh/weld.hpp"

namespace exactgeo::cli {

using io::InputError;
using io::PointReader;
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

struct Tally {
  std::size_t points = 0;
  std::array<std::size_t, 3> by_location{};  // indexed by inside::Location
  double seconds = 0.0;
  double read_seconds = 0.0;
};

/// Appends `"labels": ["inside", ...]` to `out`, a few thousand labels per write.
void print_json_labels(const std::vector<inside::Location>& labels, std::ostream& out) {
  std::string text = ", \"labels\": [";
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (i > 0) text += ", ";
    text.push_back('"');
    text.append(to_string(labels[i]));
    text.push_back('"');
    if (text.size() > (std::size_t{1} << 16)) {
      out << text;
      text.clear();
    }
  }
  out << text << "]";
}

mesh::LoadOptions load_options(const InsideCommandOptions& options) {
  return {.weld = options.weld,
          .split_polygons = options.split_polygons,
          .format = options.mesh_format};
}

/// A mesh refused by its checks, explained: the checks' message in the file's own
/// numbering (OBJ counts vertices and faces from 1, OFF and PLY from 0), saying which, and
/// whether merging the vertices that repeat another's coordinates (--weld) would make it
/// acceptable. `message` as it is when the refusal was not the checks'. Only on this error
/// path is the file read a second time.
std::string refusal_explained(const InsideCommandOptions& options, const std::string& message) {
  if (options.mesh == "-") return message;  // standard input cannot be read again
  try {
    LoadedMesh loaded = load_mesh(options.mesh, load_options(options));
    const auto problem = mesh::closed_surface_problem(mesh::check_mesh(loaded.mesh), loaded,
                                                      options.allow_non_manifold);
    if (!problem) return message;
    std::string text = *problem;
    if (options.weld) return text;
    const std::size_t merged = mesh::weld_vertices(loaded.mesh);
    if (merged > 0 &&
        !mesh::closed_surface_problem(mesh::check_mesh(loaded.mesh), options.allow_non_manifold)) {
      text += "; with --weld, which merges the " + std::to_string(merged) +
              " vertices that repeat another's coordinates, it is accepted";
    }
    return text;
  } catch (const std::exception&) {
    return message;
  }
}

}  // namespace

ExitCode run_inside(const InsideCommandOptions& options, std::istream& in,
                    const std::string& points_source, std::ostream& out, std::ostream& err) {
  std::optional<inside::Classifier> classifier;
  std::optional<inside::FloatRayParity> float_rays;
  double build_seconds = 0.0;
  if (options.mesh == "-" && options.points == "-") {
    err << "exactgeo inside: the mesh and the points cannot both come from standard input\n";
    return ExitCode::input_error;
  }
  try {
    LoadedMesh loaded = load_mesh(options.mesh, load_options(options));
    const Clock::time_point start = Clock::now();
    if (options.float_rays) {
      // The same meshes as the classifier accepts, so that the two are compared on them.
      const mesh::MeshCheck check = mesh::check_mesh(loaded.mesh);
      if (auto problem = mesh::closed_surface_problem(check, options.allow_non_manifold)) {
        throw std::invalid_argument(*problem);
      }
      float_rays.emplace(loaded.mesh);
    } else {
      inside::ClassifierOptions classifier_options;
      classifier_options.allow_non_manifold = options.allow_non_manifold;
      // The plain double baseline casts a ray for every point (classifier.hpp).
      classifier_options.space_cells =
          options.space_cells && options.arithmetic != Arithmetic::plain_double;
      classifier.emplace(std::move(loaded.mesh), classifier_options);
    }
    build_seconds = seconds_since(start);
  } catch (const InputError& e) {
    err << "exactgeo inside: " << e.what() << "\n";
    return ExitCode::input_error;
  } catch (const std::invalid_argument& e) {
    err << "exactgeo inside: " << options.mesh << ": " << refusal_explained(options, e.what())
        << "\n";
    return ExitCode::input_error;
  } catch (const std::exception& e) {  // Embree failing, or memory running out
    err << "exactgeo inside: " << options.mesh
        << ": cannot build the search structure: " << e.what() << "\n";
    return ExitCode::input_error;
  }

  Tally tally;
  PointReader reader(in, points_source,
                     options.points_format.value_or(io::default_point_format(options.points)));
  const bool print_labels = !options.json;
  const bool keep_labels = options.json && options.labels;  // printed with the counts, at the end
  std::span<const Point3> block;
  std::vector<inside::Location> locations;
  std::vector<inside::Location> kept;
  std::string text;
  const auto read_block = [&] {
    const Clock::time_point start = Clock::now();
    block = reader.read_block(kBlockPoints);
    tally.read_seconds += seconds_since(start);
  };
  try {
    for (read_block(); !block.empty(); read_block()) {
      locations.resize(block.size());
      const Clock::time_point start = Clock::now();
      if (float_rays) {
        inside::classify_batch(*float_rays, block, locations, options.threads);
      } else {
        inside::classify_batch(*classifier, block, locations, options.arithmetic, options.threads);
      }
      tally.seconds += seconds_since(start);
      tally.points += block.size();
      text.clear();
      for (const inside::Location l : locations) {
        ++tally.by_location[static_cast<std::size_t>(l)];
        if (print_labels) text.append(to_string(l)).push_back('\n');
      }
      if (keep_labels) kept.insert(kept.end(), locations.begin(), locations.end());
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
        << (options.float_rays ? "embree" : to_string(options.arithmetic)) << "\""
        << ", \"build_seconds\": " << build_seconds << ", \"read_seconds\": " << tally.read_seconds
        << ", \"seconds\": " << tally.seconds;
    if (const auto cells = classifier ? classifier->space_cells() : std::nullopt) {
      out << ", \"space_cells\": {\"resolution\": [" << cells->resolution[0] << ", "
          << cells->resolution[1] << ", " << cells->resolution[2]
          << "], \"cells\": " << cells->cells << ", \"surface_cells\": " << cells->surface_cells
          << ", \"components\": " << cells->components << "}";
    }
    if (keep_labels) print_json_labels(kept, out);
    out << "}\n";
  }
  out << std::flush;
  return ExitCode::success;
}

CLI::App& add_inside_command(CLI::App& app, InsideCommandOptions& options) {
  CLI::App* sub = app.add_subcommand(
      "inside",
      "Classify points against a closed quad/triangle mesh, exactly: one word per point "
      "(inside, outside or boundary), in input order. POINTS is text (three numbers per line: "
      "decimal or hexfloat, separated by spaces and/or commas; '#' comments), raw "
      "little-endian float64 triples (f64), or a NumPy .npy array of shape (n, 3), float64.");
  sub->add_option("mesh", options.mesh,
                  "OBJ, OFF or PLY (exact), or any format assimp reads; - for standard input "
                  "(with --format and a POINTS file)")
      ->required();
  add_mesh_format_option(*sub, options.mesh_format);
  sub->add_option("points", options.points, "points file, or - for standard input (default)");
  sub->add_option_function<std::string>(
         "--method",
         [&options](const std::string& m) {
           options.float_rays = m == "embree";
           if (!options.float_rays) options.arithmetic = *parse_arithmetic(m);
         },
         "exact (default), double (the same traversal in plain doubles: fast, not exact) or "
         "embree (one float ray per point through Embree's own quads and triangles, hits "
         "counted: what float ray-casting tools do; a baseline, wrong on grazing rays, never "
         "boundary)")
      ->check(CLI::IsMember({"exact", "double", "embree"}));
  sub->add_option("--threads", options.threads, "worker threads (default: all hardware threads)")
      ->check(CLI::Range(1u, 1024u));
  sub->add_option_function<std::string>(
         "--points-format",
         [&options](const std::string& f) { options.points_format = io::parse_point_format(f); },
         "text, f64 or npy (default: npy for a POINTS path ending in .npy, else text)")
      ->check(CLI::IsMember({"text", "f64", "npy"}));
  CLI::Option* json =
      sub->add_flag("--json", options.json,
                    "print one JSON object (counts; build, read and classification seconds) "
                    "instead of the labels");
  sub->add_flag("--labels", options.labels,
                "with --json: the labels too, as \"labels\": [...] in input order (held in "
                "memory until the end, one byte per point)")
      ->needs(json);
  sub->add_flag("--weld", options.weld, "merge vertices with exactly equal coordinates");
  sub->add_flag("--split-polygons", options.split_polygons,
                "split faces with more than four corners into triangle fans");
  sub->add_flag("--allow-non-manifold", options.allow_non_manifold,
                "accept edges shared by 4, 6, ... faces (parity is still defined)");
  sub->add_flag("!--no-space-cells", options.space_cells,
                "cast a ray for every point, also where the certified space cells already "
                "know the label (for measuring them)");
  return *sub;
}

}  // namespace exactgeo::cli
