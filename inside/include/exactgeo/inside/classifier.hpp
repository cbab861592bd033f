#pragma once

// Exact point-in-volume classification against a closed mesh of bilinear patches and
// triangles (the inside semantics of docs/architecture.md, "Contracts").
//
// A point is `boundary` if it lies exactly on a face, else `inside` or `outside` by the
// parity of the crossings of a ray from it with the faces. Rays follow the fixed sequence
// of exactgeo/predicates/ray_directions.hpp; a ray that meets a face's edge or vertex,
// or lies in the plane of a flat face, is discarded for the next one, which the sequence
// guarantees ends. Embree proposes candidate faces along each ray; the exact predicates
// (ray_patch_parity, classify_ray_triangle) decide every one.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/arithmetic.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::inside {

/// Where candidate faces come from.
enum class CandidateSearch : std::uint8_t {
  embree,       ///< a BVH over conservative float boxes (the default)
  brute_force,  ///< every face for every ray: the reference the BVH is tested against
};

struct ClassifierOptions {
  CandidateSearch candidates = CandidateSearch::embree;
  /// Accept edges shared by four, six, ... faces (parity is still well defined when every
  /// edge has an even number of faces); by default only closed manifold meshes are accepted.
  bool allow_non_manifold = false;
  /// Certified space cells (internal/space_cells.hpp): points in a cell that no face
  /// reaches get that cell's exact label without a ray. Exact and rational arithmetic
  /// only; the plain double baseline always casts rays.
  bool space_cells = true;
};

/// Scratch memory for one thread's queries (the candidate list), reused between calls.
struct ClassifierScratch {
  std::vector<std::uint32_t> candidates;
};

class Classifier {
 public:
  /// Checks the mesh (check_mesh, closed_surface_problem) and builds the candidate search.
  /// Throws std::invalid_argument with the problem's description if the mesh cannot be
  /// classified against, std::runtime_error if Embree fails.
  explicit Classifier(mesh::Mesh mesh, ClassifierOptions options = {});
  ~Classifier();
  Classifier(Classifier&&) noexcept;
  Classifier& operator=(Classifier&&) noexcept;

  /// The location of `point` (finite coordinates). With Arithmetic::exact the answer is
  /// exact; plain_double runs the same traversal with plain double signs and per-face
  /// spans found in plain doubles (fast, can be wrong; after 64 degenerate rays it calls
  /// the point outside); rational is a slow reference.
  /// Thread-safe: concurrent calls need their own scratch.
  Location classify(const Point3& point, Arithmetic arithmetic, ClassifierScratch& scratch) const;
  Location classify(const Point3& point, Arithmetic arithmetic = Arithmetic::exact) const;

  const mesh::Mesh& mesh() const noexcept;

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
  static Location cast_rays(const State& s, const Point3& point, Arithmetic arithmetic,
                            ClassifierScratch& scratch);
  std::unique_ptr<State> state_;
};

}  // namespace exactgeo::inside
