#pragma once

// Embree, loaded the first time a mesh needs it instead of with every program that links
// exactgeo::inside. Linked at build time, libembree3 (and the TBB it pulls in) is mapped
// and relocated at every start of the command line and of the Python module, a large
// share of a short command's run (measured in docs/inside.md, "End to end"). So it is
// opened with dlopen on
// first use, and the few rtc functions exactgeo::inside calls are found by dlsym and
// called through this table. Its headers stay: the types, constants and inline helpers
// (rtcInitIntersectContext) come from them. No public header includes this one: Embree
// stays out of exactgeo's interface.

#include <embree3/rtcore.h>

#include <string>
#include <variant>

namespace exactgeo::inside::internal {

/// The rtc functions exactgeo::inside calls, each named as Embree names it.
struct EmbreeFunctions {
  decltype(&::rtcNewDevice) rtcNewDevice = nullptr;
  decltype(&::rtcReleaseDevice) rtcReleaseDevice = nullptr;
  decltype(&::rtcGetDeviceError) rtcGetDeviceError = nullptr;
  decltype(&::rtcGetDeviceProperty) rtcGetDeviceProperty = nullptr;
  decltype(&::rtcNewScene) rtcNewScene = nullptr;
  decltype(&::rtcReleaseScene) rtcReleaseScene = nullptr;
  decltype(&::rtcSetSceneFlags) rtcSetSceneFlags = nullptr;
  decltype(&::rtcGetSceneFlags) rtcGetSceneFlags = nullptr;
  decltype(&::rtcSetSceneBuildQuality) rtcSetSceneBuildQuality = nullptr;
  decltype(&::rtcCommitScene) rtcCommitScene = nullptr;
  decltype(&::rtcNewGeometry) rtcNewGeometry = nullptr;
  decltype(&::rtcReleaseGeometry) rtcReleaseGeometry = nullptr;
  decltype(&::rtcCommitGeometry) rtcCommitGeometry = nullptr;
  decltype(&::rtcAttachGeometry) rtcAttachGeometry = nullptr;
  decltype(&::rtcSetNewGeometryBuffer) rtcSetNewGeometryBuffer = nullptr;
  decltype(&::rtcSetGeometryUserPrimitiveCount) rtcSetGeometryUserPrimitiveCount = nullptr;
  decltype(&::rtcSetGeometryUserData) rtcSetGeometryUserData = nullptr;
  decltype(&::rtcSetGeometryBoundsFunction) rtcSetGeometryBoundsFunction = nullptr;
  decltype(&::rtcSetGeometryIntersectFunction) rtcSetGeometryIntersectFunction = nullptr;
  decltype(&::rtcSetGeometryOccludedFunction) rtcSetGeometryOccludedFunction = nullptr;
  decltype(&::rtcSetGeometryIntersectFilterFunction) rtcSetGeometryIntersectFilterFunction =
      nullptr;
  decltype(&::rtcIntersect1) rtcIntersect1 = nullptr;
  decltype(&::rtcOccluded1) rtcOccluded1 = nullptr;
};

/// The library exactgeo was built against, by its soname ("libembree3.so.3").
const char* embree_soname() noexcept;

/// The functions of the library `soname`, opened with dlopen, or why it cannot be opened
/// (dlopen's reason, or the first function it lacks). Opens it again on every call: use
/// embree() for the process's one copy.
std::variant<EmbreeFunctions, std::string> load_embree(const char* soname);

/// The message for a library that could not be loaded: it names `soname`, the Debian
/// package that installs it, and `why`.
std::string embree_load_error(const char* soname, const std::string& why);

/// Embree's functions, loaded once per process on the first call (thread-safe: a
/// function-local static); throws std::runtime_error (embree_load_error) on every call
/// when the library cannot be loaded.
const EmbreeFunctions& embree();

}  // namespace exactgeo::inside::internal
