#include "cli/slice_options.hpp"

#include <CLI/CLI.hpp>

#include "cli/number_option.hpp"

namespace exactgeo::cli {

char to_char(Axis axis) noexcept {
  return static_cast<char>('x' + static_cast<int>(axis));
}

std::optional<SlicePlane> parse_slice(std::string_view text, std::string& error) {
  const auto equals = text.find('=');
  if (equals != 1 || (text[0] != 'x' && text[0] != 'y' && text[0] != 'z')) {
    error = "expected AXIS=VALUE with AXIS x, y or z (for example z=0.3), got '" +
            std::string(text) + "'";
    return std::nullopt;
  }
  std::string number_error;
  const auto value = number_option(std::string(text.substr(2)), number_error);
  if (!value) {
    error = "the value in '" + std::string(text) + "': " + number_error;
    return std::nullopt;
  }
  return SlicePlane{static_cast<Axis>(text[0] - 'x'), *value};
}

CLI::Option* add_slice_options(CLI::App& sub, SliceOptions& slice) {
  CLI::Option* plane =
      sub.add_option_function<std::string>(
             "--slice",
             [&slice](const std::string& text) {
               std::string error;
               slice.plane = parse_slice(text, error);
             },
             "draw a cross-section instead of reading POINTS: the plane AXIS=VALUE (AXIS x, y "
             "or z; VALUE decimal or hexfloat, read exactly), written to --image. Each pixel "
             "shows the exact label of its centre: inside sky blue, outside white, boundary "
             "vermillion, undecided reddish purple; the mesh's cross-section curve is drawn "
             "over it in black. The "
             "picture spans the mesh's box in the other two axes, grown by 1/32 of its longer "
             "side; to the right and up: x and y for z=..., y and z for x=..., x and z for "
             "y=...")
          ->check(CLI::Validator(
              [](std::string& text) {
                std::string error;
                return parse_slice(text, error) ? std::string() : error;
              },
              "AXIS=VALUE"));
  CLI::Option* image = sub.add_option(
      "--image", slice.image, "with --slice: the PNG file to write (written whole or not at all)");
  sub.add_option("--resolution", slice.resolution,
                 "with --slice: pixels along the picture's longer side (default 1024)")
      ->check(CLI::Range(SliceOptions::kMinResolution, SliceOptions::kMaxResolution))
      ->needs(plane);
  plane->needs(image);
  image->needs(plane);
  return plane;
}

}  // namespace exactgeo::cli
