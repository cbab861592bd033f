// One Embree device and scene owned together, and Embree's failures as exceptions
// (internal/embree_scene.hpp): the message names what failed and Embree's error code (the
// device's pending one when a device is given, which reading clears; RTC_ERROR_UNKNOWN
// without a device); the scene is robust, and once committed a ray finds the triangle
// attached to it; commit() reports an error Embree left on the device. Embree's library is
// opened once per process (internal/embree_library.hpp), and one that cannot be opened is
// named with the reason.

#include "exactgeo/inside/internal/embree_scene.hpp"

#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <variant>

namespace exactgeo::inside {
namespace {

using internal::EmbreeScene;
using internal::throw_embree_error;

/// The message of the std::runtime_error `f` throws; a test failure if it throws nothing.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

/// No geometry type of Embree's (its types lie between 0 and 121; 99 is none of them).
const auto kNoGeometryType = static_cast<RTCGeometryType>(99);

std::string code(RTCError error) {
  return std::to_string(static_cast<int>(error));
}

TEST(EmbreeScene, ErrorsNameWhatFailedAndTheCode) {
  EXPECT_EQ(error_of([] { throw_embree_error(RTC_ERROR_OUT_OF_MEMORY, "cannot build it"); }),
            "Embree: cannot build it (error " + code(RTC_ERROR_OUT_OF_MEMORY) + ")");
  EXPECT_EQ(error_of([] { throw_embree_error(RTCDevice{nullptr}, "cannot create a device"); }),
            "Embree: cannot create a device (error " + code(RTC_ERROR_UNKNOWN) + ")");
}

TEST(EmbreeScene, ARobustSceneFindsItsTriangle) {
  EmbreeScene embree;
  const internal::EmbreeFunctions& rtc = embree.rtc();
  ASSERT_NE(embree.device(), nullptr);
  ASSERT_NE(embree.scene(), nullptr);
  EXPECT_EQ(rtc.rtcGetSceneFlags(embree.scene()), RTC_SCENE_FLAG_ROBUST);
  RTCGeometry triangle = rtc.rtcNewGeometry(embree.device(), RTC_GEOMETRY_TYPE_TRIANGLE);
  ASSERT_NE(triangle, nullptr);
  auto* v = static_cast<float*>(rtc.rtcSetNewGeometryBuffer(
      triangle, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3));
  auto* i = static_cast<unsigned*>(rtc.rtcSetNewGeometryBuffer(
      triangle, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), 1));
  ASSERT_NE(v, nullptr);
  ASSERT_NE(i, nullptr);
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};  // the triangle z = 0, x, y >= 0
  for (int k = 0; k < 9; ++k)
    v[k] = corners[k];
  i[0] = 0;
  i[1] = 1;
  i[2] = 2;
  rtc.rtcCommitGeometry(triangle);
  rtc.rtcAttachGeometry(embree.scene(), triangle);
  rtc.rtcReleaseGeometry(triangle);
  EXPECT_NO_THROW(embree.commit());
  // Straight down through (1/4, 1/4, 0), and beside the triangle at (1, 1, 0).
  for (const float x : {0.25f, 1.0f}) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit hit{};
    hit.ray.org_x = x;
    hit.ray.org_y = x;
    hit.ray.org_z = 1;
    hit.ray.dir_z = -1;
    hit.ray.tfar = std::numeric_limits<float>::infinity();
    hit.ray.mask = std::numeric_limits<unsigned>::max();
    hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtc.rtcIntersect1(embree.scene(), &context, &hit);
    if (x < 0.5f) {
      EXPECT_NE(hit.hit.geomID, RTC_INVALID_GEOMETRY_ID);
      EXPECT_EQ(hit.ray.tfar, 1.0f);
    } else {
      EXPECT_EQ(hit.hit.geomID, RTC_INVALID_GEOMETRY_ID);
    }
  }
}

TEST(EmbreeScene, CommitReportsAnErrorLeftOnTheDevice) {
  EmbreeScene embree;
  const internal::EmbreeFunctions& rtc = embree.rtc();
  EXPECT_NO_THROW(embree.commit());  // an empty scene builds
  // A geometry type Embree does not know: no geometry, and an error on the device.
  EXPECT_EQ(rtc.rtcNewGeometry(embree.device(), kNoGeometryType), nullptr);
  const std::string message = error_of([&] { embree.commit(); });
  EXPECT_EQ(message.rfind("Embree: cannot build the scene (error ", 0), 0u) << message;
  EXPECT_EQ(message.find("(error " + code(RTC_ERROR_NONE) + ")"), std::string::npos) << message;
  // The code was read, and reading cleared it: the next commit succeeds, and a device's
  // error is read from the device.
  EXPECT_NO_THROW(embree.commit());
  EXPECT_EQ(rtc.rtcNewGeometry(embree.device(), kNoGeometryType), nullptr);
  const std::string from_device =
      error_of([&] { throw_embree_error(embree.device(), "cannot create user geometry"); });
  const std::string the_code = message.substr(message.find("(error"));  // the same error
  EXPECT_EQ(from_device, "Embree: cannot create user geometry " + the_code);
  EXPECT_EQ(rtc.rtcGetDeviceError(embree.device()), RTC_ERROR_NONE);
}

TEST(EmbreeLibrary, IsLoadedOncePerProcessWithEveryFunction) {
  const internal::EmbreeFunctions& rtc = internal::embree();
  EXPECT_EQ(&rtc, &internal::embree());
  EXPECT_EQ(&EmbreeScene().rtc(), &rtc);
  EXPECT_STREQ(internal::embree_soname(), "libembree3.so.3");
  const auto again = internal::load_embree(internal::embree_soname());
  ASSERT_TRUE(std::holds_alternative<internal::EmbreeFunctions>(again));
  // dlopen hands out the one copy of a library: the same functions.
  EXPECT_EQ(std::get<internal::EmbreeFunctions>(again).rtcOccluded1, rtc.rtcOccluded1);
  EXPECT_NE(rtc.rtcNewDevice, nullptr);
  EXPECT_NE(rtc.rtcSetGeometryIntersectFilterFunction, nullptr);
}

TEST(EmbreeLibrary, ALibraryThatCannotBeOpenedIsNamedWithTheReason) {
  const auto missing = internal::load_embree("libembree3-not-installed.so.3");
  ASSERT_TRUE(std::holds_alternative<std::string>(missing));
  const std::string why = std::get<std::string>(missing);
  EXPECT_NE(why.find("libembree3-not-installed.so.3"), std::string::npos) << why;
  const std::string message = internal::embree_load_error("libembree3.so.3", why);
  EXPECT_EQ(message.rfind("Embree (libembree3.so.3; Debian package libembree3-3) could not be "
                          "loaded: ",
                          0),
            0u)
      << message;
  EXPECT_NE(message.find(why), std::string::npos) << message;
}

TEST(EmbreeLibrary, ALibraryWithoutEmbreesFunctionsNamesTheFirstMissing) {
  // The C library opens, and has no rtc function.
  const auto other = internal::load_embree("libc.so.6");
  ASSERT_TRUE(std::holds_alternative<std::string>(other));
  EXPECT_EQ(std::get<std::string>(other), "libc.so.6 has no function rtcNewDevice");
}

}  // namespace
}  // namespace exactgeo::inside
