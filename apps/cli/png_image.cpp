#include "cli/png_image.hpp"

#include <png.h>

#include <cstring>
#include <limits>
#include <stdexcept>

namespace exactgeo::cli {

std::string png_bytes(const RgbImage& image) {
  constexpr std::size_t kMaxSide = std::numeric_limits<png_int_32>::max() / 3;  // row stride
  if (image.width == 0 || image.height == 0 || image.width > kMaxSide || image.height > kMaxSide ||
      image.pixels.size() != image.width * image.height * 3) {
    throw std::invalid_argument("the image's size does not match its pixels");
  }
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  const auto stride = static_cast<png_int_32>(image.width * 3);
  // Twice: once for the size, once into a buffer of that size.
  png_alloc_size_t size = 0;
  int encoded =
      png_image_write_to_memory(&png, nullptr, &size, 0, image.pixels.data(), stride, nullptr);
  std::string bytes(size, '\0');
  if (encoded != 0) {
    encoded = png_image_write_to_memory(&png, bytes.data(), &size, 0, image.pixels.data(), stride,
                                        nullptr);
  }
  const std::string message = png.message;
  png_image_free(&png);
  if (encoded == 0) throw std::runtime_error("libpng: " + message);
  bytes.resize(size);
  return bytes;
}

}  // namespace exactgeo::cli
