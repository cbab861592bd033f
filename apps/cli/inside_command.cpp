#include "cli/inside_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "cli/inside_mesh.hpp"
#include "cli/json.hpp"
#include "cli/mesh_load_options.hpp"
#include "cli/progress_line.hpp"
#include "cli/progress_option.hpp"
#include "cli/seconds.hpp"
#include "cli/slice_command.hpp"
#include "cli/threads_option.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/point_reader.hpp"
#include "exactgeo/mesh/load.hpp"

namespace exactgeo::cli {

using io::InputError;
using io::PointReader;

namespace {

/// Points per block: large enough to keep every thread busy, small enough that memory
/// stays flat (about 2 MB of points and labels).
constexpr std::size_t kBlockPoints = std::size_t{1} << 16;

struct Tally {
  std::size_t points = 0;
  inside::LocationCounts by_location;
  double seconds = 0.0;
  double read_seconds = 0.0;
};

/// The size of a regular file, or nullopt (standard input, a pipe).
std::optional<double> file_size(const std::string& path) {
  std::error_code error;
  if (path == "-" || !std::filesystem::is_regular_file(path, error)) return std::nullopt;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size == 0) return std::nullopt;
  return static_cast<double>(size);
}

/// How much of the points file has been read, by its bytes (the reader reads ahead a
/// little, which a progress line does not mind).
std::optional<double> share_read(std::istream& in, std::optional<double> bytes) {
  if (!bytes) return std::nullopt;
  if (in.eof()) return 1.0;  // tellg() answers -1 once the end has been reached
  const std::streamoff position = in.tellg();
  if (position < 0) return std::nullopt;
  return std::min(1.0, static_cast<double>(position) / *bytes);
}

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

}  // namespace

ExitCode run_inside(const InsideCommandOptions& options, std::istream& in,
                    const std::string& points_source, std::ostream& out, std::ostream& err) {
  if (options.slice.plane) return run_slice(options.mesh, options.slice, options.json, out, err);
  if (options.mesh.path == "-" && options.points == "-") {
    err << "exactgeo inside: the mesh and the points cannot both come from standard input\n";
    return ExitCode::input_error;
  }
  if (options.winding && options.mesh.float_rays) {
    err << "exactgeo inside: --winding needs the classifier (--method exact or double); the "
           "embree baseline only counts parity\n";
    return ExitCode::input_error;
  }
  ProgressLine progress(err, options.progress, "points");
  const std::optional<double> points_bytes = file_size(options.points);
  InsideMeshOptions mesh_options = options.mesh;
  if (points_bytes) {
    // 24 bytes a point in binary; text takes more, so this counts text's points high.
    mesh_options.expected_points = static_cast<std::size_t>(*points_bytes / 24);
  }
  const std::optional<InsideMesh> built = build_inside_mesh(mesh_options, err, &progress);
  if (!built) return ExitCode::input_error;
  // Against an open surface --winding prints the generalized winding number, a real number.
  const bool real_windings = options.winding && built->classifier->open();
  if (options.winding && !real_windings && !built->classifier->oriented()) {
    progress.clear();
    err << "exactgeo inside: " << mesh::mesh_source_name(options.mesh.path)
        << ": no winding numbers: the faces are not oriented alike (some edge is used more "
           "often in one direction than in the other), so only parity labels are defined\n";
    return ExitCode::input_error;
  }
  progress.task("classifying");

  Tally tally;
  PointReader reader(in, points_source,
                     options.points_format.value_or(io::default_point_format(options.points)));
  const bool print_labels = !options.json;
  const bool keep_labels = options.json && options.labels;  // printed with the counts, at the end
  const bool keep_windings = options.json && options.winding;  // likewise
  std::string kept_windings;  // the JSON array's entries, comma-separated
  std::span<const Point3> block;
  std::vector<inside::Location> locations;
  std::vector<std::optional<std::int64_t>> windings;
  std::vector<std::optional<Enclosure>> bounds;
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
      if (real_windings) {
        bounds.resize(block.size());
        built->generalized_winding_numbers(block, bounds, options.mesh.arithmetic,
                                           options.mesh.threads);
        // The counts beside the values (--json) are the labels' own: a value within 2^-40
        // of 1/2 does not say on which side w lies, so the labels are decided separately.
        if (options.json) {
          built->classify(block, locations, options.mesh.arithmetic, options.mesh.threads);
        }
      } else if (options.winding) {
        windings.resize(block.size());
        built->winding_numbers(block, windings, options.mesh.arithmetic, options.mesh.threads);
        for (std::size_t i = 0; i < block.size(); ++i)
          locations[i] = built->classifier->location_of(windings[i]);
      } else {
        built->classify(block, locations, options.mesh.arithmetic, options.mesh.threads);
      }
      tally.seconds += seconds_since(start);
      tally.points += block.size();
      text.clear();
      for (std::size_t i = 0; i < block.size(); ++i) {
        if (keep_windings) {
          if (!kept_windings.empty()) kept_windings.append(", ");
          if (real_windings) {
            kept_windings.append(bounds[i] ? shortest(bounds[i]->midpoint()) : "null");
          } else {
            kept_windings.append(windings[i] ? std::to_string(*windings[i]) : "null");
          }
        }
        if (real_windings && print_labels) {
          const std::optional<Enclosure>& w = bounds[i];
          text.append(w ? shortest(w->midpoint()) : "boundary");
          text.push_back('\n');
          continue;
        }
        const inside::Location l = locations[i];
        tally.by_location.add(l);
        if (!print_labels) continue;
        if (options.winding && windings[i]) {
          text.append(std::to_string(*windings[i]));
        } else {
          text.append(to_string(l));
        }
        text.push_back('\n');
      }
      if (keep_labels) kept.insert(kept.end(), locations.begin(), locations.end());
      out << text;
      progress.count(tally.points, std::nullopt, share_read(in, points_bytes));
    }
  } catch (const InputError& e) {
    out << std::flush;
    progress.clear();
    err << "exactgeo inside: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  progress.clear();

  if (options.json) {
    const auto count = [&](inside::Location l) { return tally.by_location[l]; };
    out << "{\"points\": " << tally.points << ", \"inside\": " << count(inside::Location::inside)
        << ", \"outside\": " << count(inside::Location::outside)
        << ", \"boundary\": " << count(inside::Location::boundary)
        << ", \"undecided\": " << count(inside::Location::undecided) << ", \"method\": \""
        << method_name(options.mesh) << "\""
        << ", \"rule\": \"" << (built->classifier ? to_string(built->classifier->rule()) : "parity")
        << "\""
        << ", \"intersecting_face_pairs\": "
        << (built->self ? std::to_string(built->self->intersecting.size()) : "null")
        << ", \"undecided_face_pairs\": "
        << (built->self ? std::to_string(built->self->undecided.size()) : "null")
        << ", \"build_seconds\": " << built->seconds
        << ", \"self_intersection_seconds\": " << built->self_intersection_seconds
        << ", \"read_seconds\": " << tally.read_seconds << ", \"seconds\": " << tally.seconds;
    if (const auto cells = built->classifier ? built->classifier->space_cells() : std::nullopt) {
      out << ", \"space_cells\": {\"resolution\": [" << cells->resolution[0] << ", "
          << cells->resolution[1] << ", " << cells->resolution[2]
          << "], \"cells\": " << cells->cells << ", \"surface_cells\": " << cells->surface_cells
          << ", \"components\": " << cells->components << "}";
    }
    if (keep_labels) print_json_labels(kept, out);
    if (keep_windings) out << ", \"winding_numbers\": [" << kept_windings << "]";
    out << "}\n";
  }
  out << std::flush;
  return ExitCode::success;
}

CLI::App& add_inside_command(CLI::App& app, InsideCommandOptions& options) {
  CLI::App* sub = app.add_subcommand(
      "inside",
      "Classify points against a quad/triangle mesh, exactly: one word per point, in input "
      "order: inside, outside, boundary (on a face) or undecided. A closed mesh holds the "
      "points its winding number and --rule say; an open one (holes, boundary edges) those "
      "where its generalized winding number w is at least 1/2 in magnitude (--rule positive: "
      "w >= 1/2), certified, and undecided where w is exactly 1/2 or too close to it to "
      "settle. POINTS is text (three numbers per line: decimal or hexfloat, separated by "
      "spaces and/or commas; '#' comments), raw little-endian float64 triples (f64), or a "
      "NumPy .npy array of shape (n, 3), float64.");
  sub->add_option("mesh", options.mesh.path,
                  "OBJ, OFF, PLY or STL (exact), or any format assimp reads; - for standard "
                  "input (with --format and a POINTS file)")
      ->required();
  add_mesh_format_option(*sub, options.mesh.load.format);
  sub->add_option("points", options.points, "points file, or - for standard input (default)");
  sub->add_option_function<std::string>(
         "--method",
         [&options](const std::string& m) {
           options.mesh.float_rays = m == "embree";
           if (!options.mesh.float_rays) options.mesh.arithmetic = *parse_arithmetic(m);
         },
         "exact (default), double (the same traversal in plain doubles: fast, not exact) or "
         "embree (one float ray per point through Embree's own quads and triangles, hits "
         "counted: what float ray-casting tools do; a baseline, wrong on grazing rays, never "
         "boundary)")
      ->check(CLI::IsMember({"exact", "double", "embree"}));
  add_threads_option(*sub, options.mesh.threads);
  add_progress_flag(*sub, options.progress_asked);
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
  sub->add_option_function<std::string>(
         "--rule",
         [&options](const std::string& r) { options.mesh.rule = *inside::parse_fill_rule(r); },
         "which points the surface holds, by their winding numbers w (faces oriented by their "
         "corner order, counter-clockwise seen from outside): nonzero (default; w != 0: parts "
         "that overlap read as their union), parity (w odd: overlaps read outside; the only "
         "rule for faces not oriented alike) or positive (w > 0: parts turned inside out carve "
         "cavities). All three agree on a closed mesh that does not intersect itself")
      ->check(CLI::IsMember({"nonzero", "parity", "positive"}));
  sub->add_flag(
      "--winding", options.winding,
      "print each point's winding number (an integer, exact) instead of its label; against an "
      "open surface its generalized winding number (a decimal within about 2^-41 of the true "
      "value, certified); boundary for points on the surface. With --json: the values beside "
      "the counts, as \"winding_numbers\": [...] in input order (null on the surface; held in "
      "memory until the end)");
  add_weld_flag(*sub, options.mesh.load.weld);
  add_split_polygons_flag(*sub, options.mesh.load.split_polygons, " instead of refusing the mesh");
  sub->add_flag("--allow-non-manifold", options.mesh.allow_non_manifold,
                "with --rule parity: accept edges shared by 4, 6, ... faces (parity is still "
                "defined; the winding rules accept edges used as often in each direction)");
  // Faces that intersect: looked for by default only where the labels are the parity
  // solid's; either flag overrides that.
  const auto check_flag = [&](const char* name, SelfIntersectionCheck when, const char* help) {
    return sub->add_flag_callback(
        name, [&options, when] { options.mesh.self_intersection_check = when; }, help);
  };
  CLI::Option* check = check_flag(
      "--self-intersection-check", SelfIntersectionCheck::always,
      "look for faces that intersect (exact; about as long as building the search structure) "
      "also under nonzero and positive, where intersections change no winding number, to "
      "count them for --json. By default the check runs only where the labels are those of "
      "the parity solid (--rule parity, or faces not oriented alike), and warns of any");
  check->excludes(check_flag("--no-self-intersection-check", SelfIntersectionCheck::never,
                             "do not look for faces that intersect, under parity either"));
  sub->add_flag("!--no-space-cells", options.mesh.space_cells,
                "cast a ray for every point, also where the certified space cells already "
                "know the label (for measuring them)");

  // A data set: one labels file per mesh (cli/inside_batch.hpp).
  CLI::Option* output_dir = sub->add_option(
      "--output-dir", options.output_dir,
      "classify against every mesh MESH names and write each mesh's labels (one a line) to "
      "DIR/NAME.labels.txt, whole or not at all: MESH a folder (its mesh files, in every "
      "subfolder, their relative paths kept), a .txt list of mesh paths (one a line, relative "
      "to the list's folder; '#' comments) or one mesh; POINTS a file for every mesh, or a "
      "pattern where {mesh} is each mesh's path without its extension ({mesh}.points.npy). "
      "Prints a line per mesh (--json: a JSON object per line); a mesh that fails is "
      "reported and the others go on (exit code 2 at the end, nothing printed)");
  output_dir->type_name("DIR");
  sub->add_option_function<std::string>(
         "--labels-format",
         [&options](const std::string& format) {
           options.labels_format =
               format == "npy" ? BatchLabelsFormat::npy : BatchLabelsFormat::text;
         },
         "with --output-dir: each mesh's labels as text, one word a line (NAME.labels.txt, "
         "the default), or as npy, a NumPy int8 array of the Python module's codes "
         "(NAME.labels.npy: exactgeo.OUTSIDE, INSIDE, BOUNDARY, UNDECIDED), as "
         "exactgeo.dask.classify_meshes writes")
      ->check(CLI::IsMember({"text", "npy"}))
      ->needs(output_dir);
  for (const char* name : {"--winding", "--labels"})
    output_dir->excludes(sub->get_option(name));

  // A cross-section picture instead of labels (cli/slice_options.hpp).
  CLI::Option* slice = add_slice_options(*sub, options.slice);
  for (const char* name : {"points", "--labels", "--points-format", "--winding", "--output-dir"}) {
    slice->excludes(sub->get_option(name));
  }
  return *sub;
}

}  // namespace exactgeo::cli
