#pragma once

// An 8-bit RGB image encoded as PNG with libpng (its simplified API), in memory: the
// bytes are then written whole or not at all by an OutputFile (cli/output_file.hpp).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace exactgeo::cli {

/// Rows top to bottom, three bytes (red, green, blue) per pixel, no padding.
struct RgbImage {
  std::size_t width = 0;
  std::size_t height = 0;
  std::vector<std::uint8_t> pixels;  ///< width * height * 3 bytes
};

/// The PNG file's bytes. Throws std::invalid_argument when the size does not match the
/// pixels, std::runtime_error with libpng's message when it refuses.
std::string png_bytes(const RgbImage& image);

}  // namespace exactgeo::cli
