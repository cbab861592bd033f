#pragma once

// Exact point-in-volume classification against a mesh of bilinear patches and triangles
// (the inside semantics of docs/architecture.md, "Contracts").
//
// A point is `boundary` if it lies exactly on a face (faces of zero area bound nothing
// and are dropped), else `inside` or `outside` by its winding number and the fill rule
// (fill_rule.hpp): the signed count of the crossings of a ray from it with the faces.
// Rays follow the fixed sequence of exactgeo/predicates/ray_directions.hpp; a ray that
// meets a face's edge or vertex, or lies in the plane of a flat face, is discarded for
// the next one, which the sequence guarantees ends. A tree of boxes (exactgeo's own, or
// Embree's for large work: CandidateSearch) proposes candidate faces along each ray; the
// exact predicates (cross_face_signed: ray_patch_crossings, classify_ray_triangle)
// decide every one.
//
// An open surface (boundary edges, each run net once more one way than the other) is
// labelled by its generalized winding number w. With exact and rational arithmetic the
// surface F is first closed by a fixed cap on its rim (exactgeo/predicates/cap_tree.hpp):
// w = S - w_Cap, S the ray's signed count with F and the cap together, w_Cap enclosed
// between two consecutive half-integers by the cap's tree. Where that does not settle
// (the point on a cap triangle, or w_Cap too near a half-integer), and for plain doubles:
// the ray's signed count with F plus a certified term over the boundary edges
// (exactgeo/predicates/boundary_term.hpp, internal/open_label.hpp), `undecided` where no
// precision allowed settles it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/arithmetic.hpp"
#include "exactgeo/predicates/boundary_term.hpp"
#include "exactgeo/predicates/boundary_tree.hpp"
#include "exactgeo/predicates/cap_tree.hpp"
#include "exactgeo/predicates/crossing_parity.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::inside {

namespace internal {
struct OpenBoxAnswer;  // internal/open_space_cells.hpp
}  // namespace internal

/// Where candidate faces come from.
enum class CandidateSearch : std::uint8_t {
  /// exactgeo's box tree or Embree by the mesh's faces and the points expected
  /// (ClassifierOptions::expected_points): the box tree for fewer than kEmbreePoints
  /// points, for fewer than kBoxTreeFaces faces when the count is not known, and for
  /// fewer than kBoxTreeFacesManyPoints faces in any case; Embree otherwise (the default).
  /// Below those counts, loading Embree, starting its device and building its BVH cost
  /// more than its faster rays save.
  automatic,
  embree,       ///< Embree's BVH over conservative float boxes
  box_tree,     ///< exactgeo's box tree over the same boxes, rays tested in double
  brute_force,  ///< every face for every ray: the reference the trees are tested against
};

/// CandidateSearch::automatic's counts (docs/inside.md, "End to end").
inline constexpr std::size_t kBoxTreeFaces = 4096;
inline constexpr std::size_t kEmbreePoints = std::size_t{1} << 19;
inline constexpr std::size_t kBoxTreeFacesManyPoints = 256;

struct ClassifierOptions {
  CandidateSearch candidates = CandidateSearch::automatic;
  /// Parity only: accept edges shared by four, six, ... faces (parity is still well
  /// defined when every edge has an even number of faces); by default parity accepts
  /// only closed manifold meshes.
  bool allow_non_manifold = false;
  /// Certified space cells (internal/space_cells.hpp): points in a cell that no face
  /// reaches get that cell's exact label without a ray. Exact and rational arithmetic
  /// only; the plain double baseline always casts rays.
  bool space_cells = true;
  /// About how many points will be classified, where the caller knows (a points file's
  /// size): the space cells are then sized to the work as well as to the mesh, so that a
  /// few thousand points do not pay for a grid built for millions. Any value gives the
  /// same labels; nullopt sizes the cells by the mesh alone. CandidateSearch::automatic
  /// reads it too (nullopt: as many points as make Embree worth loading).
  std::optional<std::size_t> expected_points = std::nullopt;
  /// nonzero and positive need faces oriented alike (no edge run the same way by two more
  /// faces than the other way), closed or open; parity needs a closed surface.
  /// nullopt: parity for a closed surface whose faces are not oriented alike (the only
  /// rule it has), nonzero otherwise (rule() says which was taken).
  std::optional<FillRule> rule = std::nullopt;
};

/// Scratch memory for one thread's queries (the candidate list), reused between calls.
struct ClassifierScratch {
  std::vector<std::uint32_t> candidates;
  /// An open surface's boundary edges near the point and far nodes' ends.
  BoundaryTree::Refinement boundary;
  /// An open surface's cap: the candidate cap triangles for a ray, and the cap tree's far
  /// nodes.
  std::vector<std::uint32_t> cap_candidates;
  CapTree::Refinement cap;
  /// How an open surface's labels were reached, counted over the classify calls that used
  /// this scratch (exact and rational arithmetic; for tests and measurements).
  struct OpenRoutes {
    std::size_t cap = 0;   ///< labels from S - w_Cap (F's crossings and the cap's)
    std::size_t cone = 0;  ///< labels from the cone's term (the boundary tree, or every edge)
    /// Points whose ray origin lies on a cap triangle (not on F): labelled by the cone.
    std::size_t on_cap = 0;
    /// Points whose cap enclosure did not settle (w_Cap too near a half-integer, or the
    /// point within rounding of a cap triangle): labelled by the cone.
    std::size_t cap_unsettled = 0;
    /// Rays cast again because they met a cap triangle's edge or corner (or lay in its
    /// plane), F's crossings being clean.
    std::size_t cap_degenerate_rays = 0;
  };
  OpenRoutes routes;
};

class Classifier {
 public:
  /// Checks the mesh (check_mesh; orientable_surface_problem for nonzero and positive,
  /// closed_surface_problem for parity) and builds the candidate search. Throws
  /// std::invalid_argument with the problem's description if the mesh cannot be classified
  /// against by the rule, std::runtime_error if Embree is used and fails (cannot be loaded,
  /// out of memory).
  explicit Classifier(mesh::Mesh mesh, ClassifierOptions options = {});
  ~Classifier();
  Classifier(Classifier&&) noexcept;
  Classifier& operator=(Classifier&&) noexcept;

  /// The location of `point` (finite coordinates). With Arithmetic::exact the answer is
  /// exact (against an open surface: certified, or undecided); plain_double runs the same
  /// traversal with plain double signs and per-face spans found in plain doubles (fast,
  /// can be wrong; after 64 degenerate rays it calls the point outside); rational is a
  /// slow reference.
  /// Thread-safe: concurrent calls need their own scratch.
  Location classify(const Point3& point, Arithmetic arithmetic, ClassifierScratch& scratch) const;
  Location classify(const Point3& point, Arithmetic arithmetic = Arithmetic::exact) const;

  /// The winding number of `point` (finite coordinates), or nullopt when it lies on a
  /// face, in the arithmetic's sense as for classify. Throws std::logic_error when the
  /// mesh is not a closed oriented surface: accepted by the parity rule only, where the
  /// signed count depends on the ray and no winding number is defined, or open, where it
  /// is not an integer.
  std::optional<std::int64_t> winding_number(const Point3& point, Arithmetic arithmetic,
                                             ClassifierScratch& scratch) const;
  std::optional<std::int64_t> winding_number(const Point3& point,
                                             Arithmetic arithmetic = Arithmetic::exact) const;

  /// The generalized winding number of `point` (finite coordinates) as bounds certain to
  /// hold it, or nullopt when the point lies on the surface (a face, or a boundary edge of
  /// an open surface). On a closed oriented surface it is the winding number (lower ==
  /// upper); on an open one, w = S + (boundary term) (internal/open_winding.hpp), the
  /// bounds at most about 2^-40 apart except within rounding of a boundary edge's line.
  /// Arithmetic::plain_double: lower == upper, not certified. Throws std::logic_error for
  /// a closed surface whose faces are not oriented alike (no winding number is defined).
  std::optional<Enclosure> generalized_winding_number(const Point3& point, Arithmetic arithmetic,
                                                      ClassifierScratch& scratch) const;
  std::optional<Enclosure> generalized_winding_number(
      const Point3& point, Arithmetic arithmetic = Arithmetic::exact) const;

  /// The location of a point of winding number `winding` by the rule (boundary for
  /// nullopt, a point on the surface).
  Location location_of(const std::optional<std::int64_t>& winding) const noexcept;

  /// The label a certified space cell gives `point` (without a ray), or nullopt where
  /// no cell labels it (outside the box, a cell some face reaches, no cells): what the
  /// cells answer, for tests and measurements.
  std::optional<Location> space_cell_label(const Point3& point) const noexcept;

  /// The mesh classified against: the one given, without its faces of zero area.
  const mesh::Mesh& mesh() const noexcept;
  /// The faces of zero area that were dropped (indices into the mesh given).
  const mesh::Examples<std::size_t>& zero_area_faces() const noexcept;
  FillRule rule() const noexcept;
  /// Every edge used as often in each direction: winding numbers are defined.
  bool oriented() const noexcept;
  /// Some edge is used net once more in one direction (a boundary): labels come from
  /// the generalized winding number.
  bool open() const noexcept;
  /// The boundary of an open surface (empty for a closed one).
  std::span<const BoundaryEdge> boundary() const noexcept;
  /// What the label of a point against this open surface means, for a user: "the
  /// surface is open (12 boundary edges): inside where its generalized winding number
  /// ..."; nullopt for a closed surface.
  std::optional<std::string> open_note() const;

  /// The space cells' size, when they are on: the grid's cells, those some face reaches
  /// (their points cast rays), and the components of the others (one exact ray each).
  struct CellSummary {
    std::array<std::size_t, 3> resolution;
    std::size_t cells;
    std::size_t surface_cells;
    std::size_t components;
  };
  std::optional<CellSummary> space_cells() const noexcept;

 private:
  struct State;
  /// A query point as the exact rays see it (internal/unit_frame.hpp).
  struct RayOrigin;
  /// The signed crossing count along the first decisive ray (the winding number of an
  /// oriented mesh; of the right parity for any closed one); nullopt on a face.
  static std::optional<std::int64_t> cast_rays(const State& s, const Point3& point,
                                               Arithmetic arithmetic, ClassifierScratch& scratch);
  static std::optional<std::int64_t> signed_count(const State& s, const Point3& point,
                                                  Arithmetic arithmetic,
                                                  ClassifierScratch& scratch);
  /// The signed crossings of ray k of the sequence from `origin` (a point in the box).
  template <class Signs>
  static SignedRayCount count_ray(const State& s, const Signs& signs, Arithmetic arithmetic,
                                  const RayOrigin& origin, std::size_t k,
                                  ClassifierScratch& scratch);
  /// The signed crossings of ray k with the cap's triangles (an open surface's, with exact
  /// or rational signs).
  template <class Signs>
  static SignedRayCount count_cap_ray(const State& s, const Signs& signs, const RayOrigin& origin,
                                      std::size_t k, ClassifierScratch& scratch);
  /// classify for an open surface.
  static Location classify_open(const State& s, const Point3& point, Arithmetic arithmetic,
                                ClassifierScratch& scratch);
  /// The label of every point of a box no face reaches, against an open surface, with
  /// what finding it cost (internal/open_space_cells.hpp).
  static internal::OpenBoxAnswer open_box_label(const State& s, const Point3& lower,
                                                const Point3& upper, ClassifierScratch& scratch);
  /// generalized_winding_number for an open surface.
  static std::optional<Enclosure> open_winding_number(const State& s, const Point3& point,
                                                      Arithmetic arithmetic,
                                                      ClassifierScratch& scratch);
  std::unique_ptr<State> state_;
};

}  // namespace exactgeo::inside
