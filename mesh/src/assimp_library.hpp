#pragma once

// assimp, loaded the first time a file needs it instead of with every program that links
// the mesh readers. OBJ, OFF, PLY and STL have exactgeo's own readers; assimp serves the
// other formats (glTF, FBX, 3DS, ...). Linked at build time, its library (with the zip,
// compression and Draco libraries it pulls in) is mapped and relocated at every start of
// every command and of the Python module, a large share of a short command's time
// (docs/inside.md, "End to end"). So it is opened with dlopen on first use, and only assimp's C interface (assimp/cimport.h) is
// called: plain functions whose addresses dlsym finds; the scene they return is plain data.

#include <assimp/scene.h>

#include <memory>
#include <string>
#include <string_view>

namespace exactgeo::mesh::internal {

class AssimpLibrary {
 public:
  /// The library, opened once per process; an InputError naming `source` when it cannot
  /// be (assimp not installed), with the reason.
  static const AssimpLibrary& open(const std::string& source);

  struct Release {
    const AssimpLibrary* library;
    void operator()(const aiScene* scene) const noexcept { library->release_(scene); }
  };
  using Scene = std::unique_ptr<const aiScene, Release>;

  /// assimp reads files with this extension (".gltf", leading dot).
  bool supports(const std::string& dotted_extension) const;
  /// The scene in the file, as read (no post-processing: quads stay quads); null on failure.
  Scene read_file(const std::string& path) const;
  /// The same from bytes in memory, `hint` the format's extension (no dot).
  Scene read_memory(std::string_view bytes, const std::string& hint) const;
  /// Why the last read on this thread failed.
  std::string error() const;

 private:
  using IsExtensionSupported = int (*)(const char*);
  using ImportFile = const aiScene* (*)(const char*, unsigned int);
  using ImportMemory = const aiScene* (*)(const char*, unsigned int, unsigned int, const char*);
  using ReleaseImport = void (*)(const aiScene*);
  using GetErrorString = const char* (*)();

  AssimpLibrary() = default;

  IsExtensionSupported is_extension_supported_ = nullptr;
  ImportFile import_file_ = nullptr;
  ImportMemory import_memory_ = nullptr;
  ReleaseImport release_ = nullptr;
  GetErrorString error_string_ = nullptr;
};

}  // namespace exactgeo::mesh::internal
