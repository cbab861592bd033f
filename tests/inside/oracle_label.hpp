#pragma once

// The label a fill rule gives a point of an open surface from the solid-angle oracle's
// w - 1/2 (a double): what the open-surface tests compare the classifier's labels with.

#include <cmath>
#include <optional>

#include "exactgeo/inside/classifier.hpp"

namespace exactgeo::testing {

/// The rule's label for w given w - 1/2; nullopt where the oracle's double cannot tell.
inline std::optional<inside::Location> label_from_oracle(inside::FillRule rule, double above_half) {
  constexpr double kTooNear = 0x1p-40;  // w +- 1/2 from one double: no closer
  if (std::abs(above_half) < kTooNear) return std::nullopt;
  if (rule == inside::FillRule::positive) {
    return above_half > 0 ? inside::Location::inside : inside::Location::outside;
  }
  const double above_minus_half = above_half + 1.0;
  if (std::abs(above_minus_half) < kTooNear) return std::nullopt;
  return above_half > 0 || above_minus_half < 0 ? inside::Location::inside
                                                : inside::Location::outside;
}

}  // namespace exactgeo::testing
