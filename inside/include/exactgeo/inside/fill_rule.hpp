#pragma once

// Which points a closed surface holds. Every face is oriented by its corner order, and a
// point off the surface has a winding number w: the signed number of times the surface
// wraps around it (+1 inside a simple solid whose faces are counter-clockwise seen from
// outside, 2 where two such solids overlap, -1 inside one turned inside out). Rays count
// it exactly (crossing_parity.hpp). A rule turns w into inside or outside.
//
// On a closed surface that does not intersect itself and is oriented consistently, w is 0
// outside and +1 (or -1 throughout, if every face is turned) inside, and the three rules
// agree. They differ where parts overlap, nest or fold through each other.
//
// An open surface (holes, boundary edges) has a generalized winding number instead, a
// real number (exactgeo/predicates/boundary_term.hpp): nonzero puts a point inside where
// |w| >= 1/2, positive where w >= 1/2; parity needs a closed surface.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/loaded_mesh.hpp"

namespace exactgeo::inside {

enum class FillRule : std::uint8_t {
  /// Inside where w != 0: overlapping parts read as their union, and a surface turned
  /// inside out as a whole still holds its interior. The default: it is what a mesh made
  /// of overlapping closed parts (a character's separate limbs and eyes, an assembly,
  /// merged scans) means.
  nonzero,
  /// Inside where w is odd, the crossing parity: an overlap of two parts reads outside.
  /// The only rule that needs no orientation (any closed surface, every edge shared by an
  /// even number of faces).
  parity,
  /// Inside where w > 0: a part turned inside out carves a cavity out of the parts around
  /// it.
  positive,
};

std::string_view to_string(FillRule rule) noexcept;
/// "nonzero", "parity" or "positive"; nullopt for anything else.
std::optional<FillRule> parse_fill_rule(std::string_view text) noexcept;

/// The rule a classifier takes: `asked`, or by default parity for a closed surface whose
/// faces are not oriented alike (a misoriented edge: the only rule such a mesh has), and
/// nonzero otherwise (closed oriented surfaces, and open ones).
FillRule rule_for(const mesh::MeshCheck& check, std::optional<FillRule> asked) noexcept;

/// What keeps the mesh from being classified by `rule`: mesh::closed_surface_problem for
/// parity (with allow_non_manifold), mesh::orientable_surface_problem for the winding
/// rules (closed or open);
/// nullopt if nothing. With `loaded`, in the file's own numbering, saying which.
std::optional<std::string> rule_problem(const mesh::MeshCheck& check, FillRule rule,
                                        bool allow_non_manifold);
std::optional<std::string> rule_problem(const mesh::MeshCheck& check, FillRule rule,
                                        bool allow_non_manifold, const mesh::LoadedMesh& loaded);

/// How a caller spells the options a refusal points to: the command line's flags or
/// Python's keywords. An empty name is an option the caller does not offer (the float ray
/// baseline counts parity whatever the rule).
struct OptionNames {
  std::string_view parity;              ///< "--rule parity"
  std::string_view nonzero;             ///< "--rule nonzero"
  std::string_view allow_non_manifold;  ///< "--allow-non-manifold"
  std::string_view weld;                ///< "--weld"
};
inline constexpr OptionNames kCommandLineNames{"--rule parity", "--rule nonzero",
                                               "--allow-non-manifold", "--weld"};
inline constexpr OptionNames kPythonNames{"rule='parity'", "rule='nonzero'",
                                          "allow_non_manifold=True", "weld=True"};

/// A face soup's problem: the mesh has boundary edges only because its faces do not share
/// vertices (mesh::vertices_welding_closes), and a winding rule would classify it as an
/// open surface with all those edges as its boundary: the same labels, more slowly. The
/// message names the way out (names.weld); nullopt for anything else, and when parity was
/// asked for (which refuses it as not closed).
std::optional<std::string> face_soup_problem(const mesh::LoadedMesh& loaded,
                                             std::optional<FillRule> asked,
                                             const OptionNames& names);

/// Why `rule` refuses the mesh, all at once (rule_problem in the file's numbering), and
/// every way out that would take it, tried: the other rules, allow_non_manifold, welding,
/// and `exactgeo info --mark` to see the faces named; nullopt when the rule takes it. The
/// command line and Python say the same, each with its own option names.
std::optional<std::string> refusal(const mesh::LoadedMesh& loaded, FillRule rule,
                                   bool allow_non_manifold, const OptionNames& names);

/// Does the rule put a point of winding number w inside?
constexpr bool holds(FillRule rule, std::int64_t w) noexcept {
  switch (rule) {
    case FillRule::nonzero:
      return w != 0;
    case FillRule::parity:
      return w % 2 != 0;
    case FillRule::positive:
      return w > 0;
  }
  return false;
}

}  // namespace exactgeo::inside
