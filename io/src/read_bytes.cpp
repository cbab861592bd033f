#include "exactgeo/io/read_bytes.hpp"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "exactgeo/io/input_error.hpp"

namespace exactgeo::io {

namespace {

[[noreturn]] void fail(const std::string& source, const char* what) {
  std::string message = source;
  message.append(": ");
  message.append(what);
  throw InputError(message);
}

std::ifstream open_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a mesh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open file");
  return in;
}

}  // namespace

void require_readable(const std::string& path) {
  (void)open_file(path);
}

std::string read_file(const std::string& path) {
  std::ifstream in = open_file(path);
  return read_stream(in, path);
}

std::string read_stream(std::istream& in, const std::string& source) {
  std::string bytes;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    bytes.append(buffer, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) fail(source, "read error");
  return bytes;
}

}  // namespace exactgeo::io
