#include "exactgeo/inside/fill_rule.hpp"

#include <array>

namespace exactgeo::inside {

namespace {
constexpr std::array kRules{FillRule::nonzero, FillRule::parity, FillRule::positive};
}  // namespace

std::string_view to_string(FillRule rule) noexcept {
  switch (rule) {
    case FillRule::nonzero:
      return "nonzero";
    case FillRule::parity:
      return "parity";
    case FillRule::positive:
      return "positive";
  }
  return "?";
}

std::optional<FillRule> parse_fill_rule(std::string_view text) noexcept {
  for (const FillRule rule : kRules) {
    if (text == to_string(rule)) return rule;
  }
  return std::nullopt;
}

}  // namespace exactgeo::inside
