#include "cli/inside_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <iomanip>
#include <istream>
#include <ostream>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cli/json.hpp"
#include "cli/output_file.hpp"
#include "cli/png_image.hpp"
#include "cli/slice_image.hpp"

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

/// The classifier the options ask for: the exact one (in any arithmetic) or the float ray
/// baseline, which keeps no mesh of its own (a slice's outline needs it).
struct BuiltClassifier {
  std::optional<inside::Classifier> classifier;
  std::optional<inside::FloatRayParity> float_rays;
  mesh::Mesh float_rays_mesh;
  double seconds = 0.0;  ///< checking the mesh and building the search structures

  const mesh::Mesh& mesh() const { return classifier ? classifier->mesh() : float_rays_mesh; }

  void classify(std::span<const Point3> points, std::span<inside::Location> locations,
                const InsideCommandOptions& options) const {
    if (float_rays) {
      inside::classify_batch(*float_rays, points, locations, options.threads);
    } else {
      inside::classify_batch(*classifier, points, locations, options.arithmetic, options.threads);
    }
  }
};

/// Loads the mesh and builds its classifier; nullopt once the error is on `err`.
std::optional<BuiltClassifier> build_classifier(const InsideCommandOptions& options,
                                                std::ostream& err) {
  BuiltClassifier built;
  try {
    LoadedMesh loaded = load_mesh(options.mesh, load_options(options));
    const Clock::time_point start = Clock::now();
    if (options.float_rays) {
      // The same meshes as the classifier accepts, so that the two are compared on them.
      const mesh::MeshCheck check = mesh::check_mesh(loaded.mesh);
      if (auto problem = mesh::closed_surface_problem(check, options.allow_non_manifold)) {
        throw std::invalid_argument(*problem);
      }
      built.float_rays.emplace(loaded.mesh);
      built.float_rays_mesh = std::move(loaded.mesh);
    } else {
      inside::ClassifierOptions classifier_options;
      classifier_options.allow_non_manifold = options.allow_non_manifold;
      // The plain double baseline casts a ray for every point (classifier.hpp).
      classifier_options.space_cells =
          options.space_cells && options.arithmetic != Arithmetic::plain_double;
      built.classifier.emplace(std::move(loaded.mesh), classifier_options);
    }
    built.seconds = seconds_since(start);
  } catch (const InputError& e) {
    err << "exactgeo inside: " << e.what() << "\n";
    return std::nullopt;
  } catch (const std::invalid_argument& e) {
    err << "exactgeo inside: " << options.mesh << ": " << refusal_explained(options, e.what())
        << "\n";
    return std::nullopt;
  } catch (const std::exception& e) {  // Embree failing, or memory running out
    err << "exactgeo inside: " << options.mesh
        << ": cannot build the search structure: " << e.what() << "\n";
    return std::nullopt;
  }
  return built;
}

/// `inside --slice`: the cross-section picture (cli/slice_image.hpp) and a report of it.
ExitCode run_slice(const InsideCommandOptions& options, std::ostream& out, std::ostream& err) {
  const SliceOptions& slice = options.slice;
  const SlicePlane plane = *slice.plane;
  // The destination first: an unwritable path is reported before any work is done.
  std::optional<OutputFile> png;
  try {
    png.emplace(slice.image);
  } catch (const OutputFileError& e) {
    err << "exactgeo inside: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  const std::optional<BuiltClassifier> built = build_classifier(options, err);
  if (!built) return ExitCode::input_error;

  SliceGrid grid;
  try {
    grid = slice_grid(built->mesh(), plane, slice.resolution);
  } catch (const std::invalid_argument& e) {
    err << "exactgeo inside: " << options.mesh << ": " << e.what() << "\n";
    return ExitCode::input_error;
  }
  Clock::time_point start = Clock::now();
  const std::vector<inside::Location> labels =
      classify_pixels(grid, [&](std::span<const Point3> points, std::span<inside::Location> to) {
        built->classify(points, to, options);
      });
  const double classify_seconds = seconds_since(start);
  start = Clock::now();
  const std::vector<std::uint8_t> outline = outline_pixels(grid, built->mesh());
  const double outline_seconds = seconds_since(start);
  start = Clock::now();
  try {
    png->commit(png_bytes(draw_slice(grid, labels, outline)));
  } catch (const OutputFileError& e) {
    err << "exactgeo inside: " << e.what() << "\n";
    return ExitCode::input_error;
  } catch (const std::exception& e) {  // libpng refusing, or memory running out
    err << "exactgeo inside: cannot write '" << slice.image << "': " << e.what() << "\n";
    return ExitCode::input_error;
  }
  const double png_seconds = seconds_since(start);

  std::array<std::size_t, 3> by_location{};  // indexed by inside::Location
  for (const inside::Location l : labels)
    ++by_location[static_cast<std::size_t>(l)];
  const auto count = [&](inside::Location l) { return by_location[static_cast<std::size_t>(l)]; };
  const std::size_t outline_count =
      static_cast<std::size_t>(std::count(outline.begin(), outline.end(), std::uint8_t{1}));
  const ImageAxes axes = image_axes(plane.axis);
  const char horizontal = to_char(static_cast<Axis>(axes.horizontal));
  const char vertical = to_char(static_cast<Axis>(axes.vertical));
  const double right = grid.left + double(grid.width) * grid.pixel;
  const double bottom = grid.top - double(grid.height) * grid.pixel;
  const bool meets_box = grid.axis_lower <= plane.value && plane.value <= grid.axis_upper;
  const std::string_view method =
      options.float_rays ? std::string_view("embree") : to_string(options.arithmetic);
  if (options.json) {
    out << "{\"image\": " << json_string(slice.image) << ", \"width\": " << grid.width
        << ", \"height\": " << grid.height << ", \"plane\": {\"axis\": \"" << to_char(plane.axis)
        << "\", \"value\": " << shortest(plane.value) << "}, \"horizontal\": {\"axis\": \""
        << horizontal << "\", \"from\": " << shortest(grid.left) << ", \"to\": " << shortest(right)
        << "}, \"vertical\": {\"axis\": \"" << vertical << "\", \"from\": " << shortest(bottom)
        << ", \"to\": " << shortest(grid.top)
        << "}, \"plane_meets_box\": " << (meets_box ? "true" : "false")
        << ", \"inside\": " << count(inside::Location::inside)
        << ", \"outside\": " << count(inside::Location::outside)
        << ", \"boundary\": " << count(inside::Location::boundary)
        << ", \"outline\": " << outline_count << ", \"method\": \"" << method << "\""
        << ", \"build_seconds\": " << built->seconds << ", \"seconds\": " << classify_seconds
        << ", \"outline_seconds\": " << outline_seconds << ", \"png_seconds\": " << png_seconds
        << "}\n";
  } else {
    std::ostringstream report;
    const auto row = [&report](std::string_view label) -> std::ostream& {
      return report << std::left << std::setw(20) << label;
    };
    row("image") << slice.image << ", " << grid.width << " x " << grid.height << " pixels\n";
    row("plane") << to_char(plane.axis) << " = " << shortest(plane.value);
    if (!meets_box) {
      report << " (outside the mesh's " << to_char(plane.axis) << " range ["
             << shortest(grid.axis_lower) << ", " << shortest(grid.axis_upper)
             << "]: every pixel is outside)";
    }
    report << "\n";
    row("right") << horizontal << " from " << shortest(grid.left) << " to " << shortest(right)
                 << "\n";
    row("up") << vertical << " from " << shortest(bottom) << " to " << shortest(grid.top) << "\n";
    row("inside") << count(inside::Location::inside) << " pixels (sky blue)\n";
    row("outside") << count(inside::Location::outside) << " pixels (white)\n";
    row("boundary") << count(inside::Location::boundary) << " pixels (vermillion)\n";
    row("outline") << outline_count << " pixels (black, over inside and outside)\n";
    row("method") << method << "\n";
    row("seconds") << "build " << built->seconds << ", classify " << classify_seconds
                   << ", outline " << outline_seconds << ", png " << png_seconds << "\n";
    out << report.str();
  }
  out << std::flush;
  return ExitCode::success;
}

}  // namespace

ExitCode run_inside(const InsideCommandOptions& options, std::istream& in,
                    const std::string& points_source, std::ostream& out, std::ostream& err) {
  if (options.slice.plane) return run_slice(options, out, err);
  if (options.mesh == "-" && options.points == "-") {
    err << "exactgeo inside: the mesh and the points cannot both come from standard input\n";
    return ExitCode::input_error;
  }
  const std::optional<BuiltClassifier> built = build_classifier(options, err);
  if (!built) return ExitCode::input_error;

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
      built->classify(block, locations, options);
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
        << ", \"build_seconds\": " << built->seconds << ", \"read_seconds\": " << tally.read_seconds
        << ", \"seconds\": " << tally.seconds;
    if (const auto cells = built->classifier ? built->classifier->space_cells() : std::nullopt) {
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

  // A cross-section picture instead of labels (cli/slice_image.hpp).
  CLI::Option* slice =
      sub->add_option_function<std::string>(
             "--slice",
             [&options](const std::string& text) {
               std::string error;
               options.slice.plane = parse_slice(text, error);
             },
             "draw a cross-section instead of reading POINTS: the plane AXIS=VALUE (AXIS x, y "
             "or z; VALUE decimal or hexfloat, read exactly), written to --image. Each pixel "
             "shows the exact label of its centre: inside sky blue, outside white, boundary "
             "vermillion; the mesh's cross-section curve is drawn over it in black. The "
             "picture spans the mesh's box in the other two axes, grown by 1/32 of its longer "
             "side; to the right and up: x and y for z=..., y and z for x=..., x and z for "
             "y=...")
          ->check(CLI::Validator(
              [](std::string& text) {
                std::string error;
                return parse_slice(text, error) ? std::string() : error;
              },
              "AXIS=VALUE"));
  CLI::Option* image =
      sub->add_option("--image", options.slice.image,
                      "with --slice: the PNG file to write (written whole or not at all)");
  sub->add_option("--resolution", options.slice.resolution,
                  "with --slice: pixels along the picture's longer side (default 1024)")
      ->check(CLI::Range(SliceOptions::kMinResolution, SliceOptions::kMaxResolution))
      ->needs(slice);
  slice->needs(image);
  image->needs(slice);
  for (const char* name : {"points", "--labels", "--points-format"}) {
    slice->excludes(sub->get_option(name));
  }
  return *sub;
}

}  // namespace exactgeo::cli
