#pragma once

// `inside --slice AXIS=VALUE --image FILE.png [--resolution N]`: what the cross-section
// picture is asked for (the plane, read exactly; the file; the size), and the registration
// of these options. The picture itself is cli/slice_image.hpp, its run cli/slice_command.hpp.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace exactgeo::cli {

enum class Axis : std::uint8_t { x, y, z };
char to_char(Axis axis) noexcept;

/// The plane axis = value.
struct SlicePlane {
  Axis axis = Axis::z;
  double value = 0.0;
};

/// "z=0.3", "x=-0x1.8p-2": x, y or z, '=', then one whole decimal or hexfloat number read
/// exactly (number_option). nullopt, with `error` saying why, for anything else.
std::optional<SlicePlane> parse_slice(std::string_view text, std::string& error);

/// The options of `inside --slice` (InsideCommandOptions::slice).
struct SliceOptions {
  std::optional<SlicePlane> plane;  ///< set: draw a cross-section instead of reading points
  std::string image;                ///< the PNG file to write
  unsigned resolution = 1024;       ///< pixels along the picture's longer side
  static constexpr unsigned kMinResolution = 16;
  static constexpr unsigned kMaxResolution = 8192;
};

/// Registers --slice, --image and --resolution on `sub` (each of --image and --resolution
/// needs --slice, and --slice needs --image); `slice` must outlive the parse. Returns the
/// --slice option, for the subcommand to say what it excludes.
CLI::Option* add_slice_options(CLI::App& sub, SliceOptions& slice);

}  // namespace exactgeo::cli
