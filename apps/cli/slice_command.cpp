#include "cli/slice_command.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <exception>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "cli/inside_mesh.hpp"
#include "cli/json.hpp"
#include "cli/output_file.hpp"
#include "cli/png_image.hpp"
#include "cli/seconds.hpp"
#include "cli/slice_image.hpp"
#include "exactgeo/mesh/load.hpp"

namespace exactgeo::cli {

ExitCode run_slice(const InsideMeshOptions& mesh_options, const SliceOptions& slice, bool json,
                   std::ostream& out, std::ostream& err) {
  const SlicePlane plane = *slice.plane;
  // The destination first: an unwritable path is reported before any work is done.
  std::optional<OutputFile> png;
  try {
    png.emplace(slice.image);
  } catch (const OutputFileError& e) {
    err << "exactgeo inside: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  const std::optional<InsideMesh> built = build_inside_mesh(mesh_options, err);
  if (!built) return ExitCode::input_error;

  SliceGrid grid;
  try {
    grid = slice_grid(built->mesh(), plane, slice.resolution);
  } catch (const std::invalid_argument& e) {
    err << "exactgeo inside: " << mesh::mesh_source_name(mesh_options.path) << ": " << e.what()
        << "\n";
    return ExitCode::input_error;
  }
  Clock::time_point start = Clock::now();
  const std::vector<inside::Location> labels =
      classify_pixels(grid, [&](std::span<const Point3> points, std::span<inside::Location> to) {
        built->classify(points, to, mesh_options.arithmetic, mesh_options.threads);
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

  inside::LocationCounts by_location;
  for (const inside::Location l : labels)
    by_location.add(l);
  const auto count = [&](inside::Location l) { return by_location[l]; };
  const std::size_t outline_count =
      static_cast<std::size_t>(std::count(outline.begin(), outline.end(), std::uint8_t{1}));
  const ImageAxes axes = image_axes(plane.axis);
  const char horizontal = to_char(static_cast<Axis>(axes.horizontal));
  const char vertical = to_char(static_cast<Axis>(axes.vertical));
  const double right = grid.left + double(grid.width) * grid.pixel;
  const double bottom = grid.top - double(grid.height) * grid.pixel;
  const bool meets_box = grid.axis_lower <= plane.value && plane.value <= grid.axis_upper;
  const std::string_view method = method_name(mesh_options);
  if (json) {
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
        << ", \"undecided\": " << count(inside::Location::undecided)
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
             << shortest(grid.axis_lower) << ", " << shortest(grid.axis_upper) << "]"
             << (built->classifier && built->classifier->open()
                     ? ": an open surface can still hold points there)"
                     : ": every pixel is outside)");
    }
    report << "\n";
    row("right") << horizontal << " from " << shortest(grid.left) << " to " << shortest(right)
                 << "\n";
    row("up") << vertical << " from " << shortest(bottom) << " to " << shortest(grid.top) << "\n";
    row("inside") << count(inside::Location::inside) << " pixels (sky blue)\n";
    row("outside") << count(inside::Location::outside) << " pixels (white)\n";
    row("boundary") << count(inside::Location::boundary) << " pixels (vermillion)\n";
    if (const std::size_t undecided = count(inside::Location::undecided); undecided > 0) {
      row("undecided") << undecided << " pixels (reddish purple)\n";
    }
    row("outline") << outline_count << " pixels (black, over inside and outside)\n";
    row("method") << method << "\n";
    row("seconds") << "build " << built->seconds << ", classify " << classify_seconds
                   << ", outline " << outline_seconds << ", png " << png_seconds << "\n";
    out << report.str();
  }
  out << std::flush;
  return ExitCode::success;
}

}  // namespace exactgeo::cli
