#include "exactgeo/mesh/load.hpp"

#include <cctype>
#include <filesystem>
#include <iostream>

#include "assimp_reader.hpp"
#include "exactgeo/io/read_bytes.hpp"
#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "exactgeo/mesh/ply_reader.hpp"
#include "exactgeo/mesh/stl_reader.hpp"

namespace exactgeo::mesh {

using internal::read_with_assimp;
using internal::read_with_assimp_from_memory;
using io::InputError;
using io::read_file;
using io::read_stream;

namespace {

std::string lowercase(std::string text) {
  for (char& c : text)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// "stl" for "Model.STL"; empty when the file name has no extension.
std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  if (!extension.empty()) extension.erase(0, 1);  // the dot
  return lowercase(extension);
}

using Reader = LoadedMesh (*)(std::string_view, const std::string&, const LoadOptions&);

/// The exact reader of a format, or nullptr for the formats assimp reads.
Reader exact_reader(const std::string& format) {
  if (format == "obj") return read_obj;
  if (format == "off") return read_off;
  if (format == "ply") return read_ply;
  if (format == "stl") return read_stl;
  return nullptr;
}

}  // namespace

std::string mesh_source_name(const std::string& path) {
  return path == "-" ? "standard input" : path;
}

LoadedMesh load_mesh(const std::string& path, const LoadOptions& options) {
  const bool from_stdin = path == "-";
  const std::string source = mesh_source_name(path);
  const std::string format =
      options.format.empty() ? lowercase_extension(path) : lowercase(options.format);
  if (from_stdin && format.empty()) {
    throw InputError(source +
                     ": the mesh's format cannot be told from a name: give --format "
                     "(obj, off, ply, stl, or a format assimp reads)");
  }
  const Reader reader = exact_reader(format);
  if (reader == nullptr) {  // assimp always welds
    if (!from_stdin) return read_with_assimp(path, format, options);
    return read_with_assimp_from_memory(read_stream(std::cin, source), source, format, options);
  }
  const std::string bytes = from_stdin ? read_stream(std::cin, source) : read_file(path);
  // Each reader welds when options.weld asks (STL always), before it splits polygons.
  return reader(bytes, source, options);
}

}  // namespace exactgeo::mesh
