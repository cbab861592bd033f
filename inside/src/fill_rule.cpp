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
                                             std::optional<FillRule> asked,
                                             const OptionNames& names) {
  if (asked == FillRule::parity) return std::nullopt;
  // Welding closes no surface whose default rule is parity (closed already).
  const auto merged = mesh::vertices_welding_closes(loaded.mesh);
  if (!merged) return std::nullopt;
  std::string message = mesh::closed_surface_problem(mesh::check_mesh(loaded.mesh), loaded)
                            .value_or("mesh is not closed");
  message.append("; with ").append(names.weld);
  message.append(", which merges the " + std::to_string(*merged) +
                 " vertices that repeat another's coordinates, it is closed (as it is, each of "
                 "those edges would be a boundary edge of an open surface: the same labels, "
                 "more slowly)");
  return message;
}

std::optional<std::string> refusal(const mesh::LoadedMesh& loaded, FillRule rule,
                                   bool allow_non_manifold, const OptionNames& names) {
  const mesh::MeshCheck check = mesh::check_mesh(loaded.mesh);
  std::optional<std::string> problem = rule_problem(check, rule, allow_non_manifold, loaded);
  if (!problem) return std::nullopt;
  std::string& text = *problem;
  // Every option that would take the mesh as it is.
  if (!names.parity.empty() && rule != FillRule::parity &&
      !mesh::closed_surface_problem(check, true)) {
    text.append("; ").append(names.parity).append(", which needs no orientation, accepts it");
    if (!allow_non_manifold && mesh::closed_surface_problem(check, false)) {
      text.append(" with ").append(names.allow_non_manifold);
    }
  }
  if (rule == FillRule::parity && !allow_non_manifold &&
      !mesh::closed_surface_problem(check, true)) {
    text.append("; ").append(names.allow_non_manifold).append(" accepts it");
  }
  if (!names.nonzero.empty() && rule == FillRule::parity &&
      !mesh::orientable_surface_problem(check)) {
    text.append("; ").append(names.nonzero).append(" accepts it");
    if (!check.closed()) text.append(" as an open surface, by its generalized winding number");
  }
  mesh::LoadedMesh welded = loaded;
  const std::size_t merged = mesh::weld_vertices(welded.mesh);
  if (merged > 0 && !rule_problem(mesh::check_mesh(welded.mesh), rule, allow_non_manifold)) {
    text.append("; with ").append(names.weld);
    text.append(", which merges the " + std::to_string(merged) +
                " vertices that repeat another's coordinates, it is accepted");
  }
  text.append(
      "; `exactgeo info --mark OUT.ply` writes the mesh with its defective faces "
      "coloured");
  return problem;
}

}  // namespace exactgeo::inside
