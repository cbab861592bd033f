#include "assimp_library.hpp"

#include <dlfcn.h>

#include <limits>
#include <optional>
#include <variant>

#include "exactgeo/io/input_error.hpp"

namespace exactgeo::mesh::internal {

namespace {

/// The library assimp's package installs, named by its soname (set by the build from the
/// assimp it was configured with).
constexpr const char* kLibrary = EXACTGEO_ASSIMP_SONAME;

template <class Function>
Function symbol(void* handle, const char* name, std::string& missing) {
  void* address = dlsym(handle, name);
  if (address == nullptr) missing = name;
  return reinterpret_cast<Function>(address);
}

}  // namespace

const AssimpLibrary& AssimpLibrary::open(const std::string& source) {
  // Opened once; what it holds never changes after (the handle is kept for the process's
  // life, as a linked library would be).
  static const std::variant<AssimpLibrary, std::string> opened =
      []() -> std::variant<AssimpLibrary, std::string> {
    void* handle = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      return std::string(why != nullptr ? why : "dlopen failed");
    }
    AssimpLibrary library;
    std::string missing;
    library.is_extension_supported_ =
        symbol<IsExtensionSupported>(handle, "aiIsExtensionSupported", missing);
    library.import_file_ = symbol<ImportFile>(handle, "aiImportFile", missing);
    library.import_memory_ = symbol<ImportMemory>(handle, "aiImportFileFromMemory", missing);
    library.release_ = symbol<ReleaseImport>(handle, "aiReleaseImport", missing);
    library.error_string_ = symbol<GetErrorString>(handle, "aiGetErrorString", missing);
    if (!missing.empty()) return std::string(kLibrary) + " has no function " + missing;
    return library;
  }();
  if (const auto* why = std::get_if<std::string>(&opened)) {
    throw io::InputError(source + ": reading this format needs assimp (" + kLibrary +
                         "; Debian package libassimp5), which could not be loaded: " + *why);
  }
  return std::get<AssimpLibrary>(opened);
}

bool AssimpLibrary::supports(const std::string& dotted_extension) const {
  return is_extension_supported_(dotted_extension.c_str()) != 0;
}

AssimpLibrary::Scene AssimpLibrary::read_file(const std::string& path) const {
  return Scene(import_file_(path.c_str(), 0u), Release{this});
}

AssimpLibrary::Scene AssimpLibrary::read_memory(std::string_view bytes,
                                                const std::string& hint) const {
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) return Scene(nullptr, {this});
  return Scene(
      import_memory_(bytes.data(), static_cast<unsigned int>(bytes.size()), 0u, hint.c_str()),
      Release{this});
}

std::string AssimpLibrary::error() const {
  const char* why = error_string_();
  return why != nullptr ? why : "";
}

}  // namespace exactgeo::mesh::internal
