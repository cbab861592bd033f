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

FillRule rule_for(const mesh::MeshCheck& check, std::optional<FillRule> asked) noexcept {
  return asked.value_or(check.unbalanced_edges.count == 0 ? FillRule::nonzero : FillRule::parity);
}

std::optional<std::string> rule_problem(const mesh::MeshCheck& check, FillRule rule,
                                        bool allow_non_manifold) {
  return rule == FillRule::parity ? mesh::closed_surface_problem(check, allow_non_manifold)
                                  : mesh::oriented_surface_problem(check);
}

std::optional<std::string> rule_problem(const mesh::MeshCheck& check, FillRule rule,
                                        bool allow_non_manifold, const mesh::LoadedMesh& loaded) {
  return rule == FillRule::parity ? mesh::closed_surface_problem(check, loaded, allow_non_manifold)
                                  : mesh::oriented_surface_problem(check, loaded);
}

}  // namespace exactgeo::inside
