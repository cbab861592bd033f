#include "exactgeo/inside/internal/embree_library.hpp"

#include <dlfcn.h>

#include <stdexcept>

namespace exactgeo::inside::internal {
namespace {

/// Points `function` at the symbol of its name in `handle`; records the first missing one.
template <class Function>
void find(void* handle, const char* name, Function& function, std::string& missing) {
  function = reinterpret_cast<Function>(dlsym(handle, name));
  if (function == nullptr && missing.empty()) missing = name;
}

}  // namespace

const char* embree_soname() noexcept {
  return EXACTGEO_EMBREE_SONAME;  // set by the build from the Embree it was configured with
}

std::variant<EmbreeFunctions, std::string> load_embree(const char* soname) {
  // The handle is kept for the process's life, as a linked library's would be.
  void* handle = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    return std::string(why != nullptr ? why : "dlopen failed");
  }
  EmbreeFunctions f;
  std::string missing;
#define EXACTGEO_EMBREE_FIND(name) find(handle, #name, f.name, missing)
  EXACTGEO_EMBREE_FIND(rtcNewDevice);
  EXACTGEO_EMBREE_FIND(rtcReleaseDevice);
  EXACTGEO_EMBREE_FIND(rtcGetDeviceError);
  EXACTGEO_EMBREE_FIND(rtcGetDeviceProperty);
  EXACTGEO_EMBREE_FIND(rtcNewScene);
  EXACTGEO_EMBREE_FIND(rtcReleaseScene);
  EXACTGEO_EMBREE_FIND(rtcSetSceneFlags);
  EXACTGEO_EMBREE_FIND(rtcGetSceneFlags);
  EXACTGEO_EMBREE_FIND(rtcSetSceneBuildQuality);
  EXACTGEO_EMBREE_FIND(rtcCommitScene);
  EXACTGEO_EMBREE_FIND(rtcNewGeometry);
  EXACTGEO_EMBREE_FIND(rtcReleaseGeometry);
  EXACTGEO_EMBREE_FIND(rtcCommitGeometry);
  EXACTGEO_EMBREE_FIND(rtcAttachGeometry);
  EXACTGEO_EMBREE_FIND(rtcSetNewGeometryBuffer);
  EXACTGEO_EMBREE_FIND(rtcSetGeometryUserPrimitiveCount);
  EXACTGEO_EMBREE_FIND(rtcSetGeometryUserData);
  EXACTGEO_EMBREE_FIND(rtcSetGeometryBoundsFunction);
  EXACTGEO_EMBREE_FIND(rtcSetGeometryIntersectFunction);
  EXACTGEO_EMBREE_FIND(rtcSetGeometryOccludedFunction);
  EXACTGEO_EMBREE_FIND(rtcSetGeometryIntersectFilterFunction);
  EXACTGEO_EMBREE_FIND(rtcIntersect1);
  EXACTGEO_EMBREE_FIND(rtcOccluded1);
#undef EXACTGEO_EMBREE_FIND
  if (!missing.empty()) return std::string(soname) + " has no function " + missing;
  return f;
}

std::string embree_load_error(const char* soname, const std::string& why) {
  return std::string("Embree (") + soname +
         "; Debian package libembree3-3) could not be loaded: " + why;
}

const EmbreeFunctions& embree() {
  static const std::variant<EmbreeFunctions, std::string> loaded = load_embree(embree_soname());
  if (const auto* why = std::get_if<std::string>(&loaded)) {
    throw std::runtime_error(embree_load_error(embree_soname(), *why));
  }
  return std::get<EmbreeFunctions>(loaded);
}

}  // namespace exactgeo::inside::internal
