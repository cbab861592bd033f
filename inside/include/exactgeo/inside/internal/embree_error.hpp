#pragma once

// Embree failures as exceptions, for the files of exactgeo::inside that build Embree
// scenes (src/embree_candidates.cpp, src/float_ray_parity.cpp). No public header includes
// this one: Embree stays out of exactgeo's interface.

#include <embree3/rtcore.h>

#include <stdexcept>
#include <string>

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
  throw_embree_error(device != nullptr ? rtcGetDeviceError(device) : RTC_ERROR_UNKNOWN, what);
}

}  // namespace exactgeo::inside::internal
