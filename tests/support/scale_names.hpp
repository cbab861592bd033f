#pragma once

// The name of a test instantiated at the power-of-two scale 2^k: scale_2p0, scale_2p1000,
// scale_2m1000 (the names .ci/run's sanitizer exclusions match).

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace exactgeo::testing {

inline std::string scale_name(const ::testing::TestParamInfo<int>& param_info) {
  const int k = param_info.param;
  return (k < 0 ? "scale_2m" : "scale_2p") + std::to_string(std::abs(k));
}

}  // namespace exactgeo::testing
