#include "exactgeo/inside/fill_rule.hpp"

#include <array>

#include "exactgeo/mesh/weld.hpp"

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
  // A closed surface whose faces are not oriented alike has parity only.
  const bool parity_only = check.closed() && check.misoriented_edges.count > 0;
  return asked.value_or(parity_only ? FillRule::parity : FillRule::nonzero);
}

std::optional<std::string> rule_problem(const mesh::MeshCheck& check, FillRule rule,
                                        bool allow_non_manifold) {
  return rule == FillRule::parity ? mesh::closed_surface_problem(check, allow_non_manifold)
                                  : mesh::orientable_surface_problem(check);
}

std::optional<std::string> rule_problem(const mesh::MeshCheck& check, FillRule rule,
                                        bool allow_non_manifold, const mesh::LoadedMesh& loaded) {
  return rule == FillRule::parity ? mesh::closed_surface_problem(check, loaded, allow_non_manifold)
                                  : mesh::orientable_surface_problem(check, loaded);
}

std::optional<std::string> face_soup_problem(const mesh::LoadedMesh& loaded,
                                             std::optional<FillRule> asked, std::string_view weld) {
  if (asked == FillRule::parity) return std::nullopt;
  // Welding closes no surface whose default rule is parity (closed already).
  const auto merged = mesh::vertices_welding_closes(loaded.mesh);
  if (!merged) return std::nullopt;
  std::string message = mesh::closed_surface_problem(mesh::check_mesh(loaded.mesh), loaded)
                            .value_or("mesh is not closed");
  message.append("; with ").append(weld);
  message.append(", which merges the " + std::to_string(*merged) +
                 " vertices that repeat another's coordinates, it is closed (as it is, each of "
                 "those edges would be a boundary edge of an open surface: the same labels, "
                 "more slowly)");
  return message;
}

}  // namespace exactgeo::inside
