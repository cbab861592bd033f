#pragma once

// One Embree device and scene, owned together, and Embree failures as exceptions: what the
// files of exactgeo::inside that build Embree scenes share (src/embree_candidates.cpp,
// src/float_ray_parity.cpp). Embree's functions come from its library opened on first use
// (embree_library.hpp): constructing an EmbreeScene is what loads it. No public header
// includes this one: Embree stays out of exactgeo's interface.

#include <embree3/rtcore.h>

#include <stdexcept>
#include <string>

#include "exactgeo/inside/internal/embree_library.hpp"

namespace exactgeo::inside::internal {

/// Throws std::runtime_error "Embree: <what> (error <code>)".
[[noreturn]] inline void throw_embree_error(RTCError code, const char* what) {
  std::string message = "Embree: ";
  message.append(what)
      .append(" (error ")
      .append(std::to_string(static_cast<int>(code)))
      .append(")");
  throw std::runtime_error(message);
}

/// The same with the device's last error code (RTC_ERROR_UNKNOWN when there is no device).
/// Reading the code clears it: when it was read already, pass it instead.
[[noreturn]] inline void throw_embree_error(RTCDevice device, const char* what) {
  throw_embree_error(device != nullptr ? embree().rtcGetDeviceError(device) : RTC_ERROR_UNKNOWN,
                     what);
}

/// A device with one robust scene (RTC_SCENE_FLAG_ROBUST), released together. Attach
/// geometry to scene(), then commit(). The constructor loads Embree (embree()) and throws
/// std::runtime_error when it cannot.
class EmbreeScene {
 public:
  EmbreeScene() : rtc_(embree()) {
    device_ = rtc_.rtcNewDevice(nullptr);
    if (device_ == nullptr) throw_embree_error(nullptr, "cannot create a device");
    scene_ = rtc_.rtcNewScene(device_);
    if (scene_ == nullptr) {
      const RTCError error = rtc_.rtcGetDeviceError(device_);
      rtc_.rtcReleaseDevice(device_);
      throw_embree_error(error, "cannot create a scene");
    }
    rtc_.rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  }
  ~EmbreeScene() {
    rtc_.rtcReleaseScene(scene_);
    rtc_.rtcReleaseDevice(device_);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// Embree's functions, for the geometry and the rays.
  const EmbreeFunctions& rtc() const noexcept { return rtc_; }
  RTCDevice device() const noexcept { return device_; }
  RTCScene scene() const noexcept { return scene_; }

  /// Builds the scene's BVH; throws if Embree reports an error (out of memory).
  void commit() {
    rtc_.rtcCommitScene(scene_);
    const RTCError error = rtc_.rtcGetDeviceError(device_);
    if (error != RTC_ERROR_NONE) throw_embree_error(error, "cannot build the scene");
  }

 private:
  const EmbreeFunctions& rtc_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace exactgeo::inside::internal
