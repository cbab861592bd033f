#pragma once

// The mesh an `inside` run classifies against: loaded (with --format, --weld,
// --split-polygons), checked, and its search structure built, for the exact classifier (in
// any arithmetic) or the float ray baseline. A refused mesh is explained in the file's own
// numbering, with a hint when --weld would make it acceptable.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "cli/progress_line.hpp"
#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/float_ray_parity.hpp"
#include "exactgeo/mesh/loaded_mesh.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "exactgeo/predicates/arithmetic.hpp"

namespace exactgeo::cli {

/// What the classifier is built from and how it classifies: the mesh, what its checks
/// accept, the method and the threads. Nothing about the points or the report.
/// When `inside` looks for faces that intersect (--self-intersection-check,
/// --no-self-intersection-check).
enum class SelfIntersectionCheck : std::uint8_t { under_parity, always, never };

struct InsideMeshOptions {
  std::string path;        ///< a file, or "-" for standard input (with load.format)
  mesh::LoadOptions load;  ///< --format, --weld, --split-polygons
  /// --rule: which points the surface holds, by their winding numbers; nullopt: nonzero,
  /// or parity (with a warning) for faces not oriented alike. The float ray baseline
  /// counts parity whatever it says.
  std::optional<inside::FillRule> rule = std::nullopt;
  bool allow_non_manifold = false;  ///< parity only (the winding rules need no permission)
  Arithmetic arithmetic = Arithmetic::exact;
  /// The float ray baseline (inside/float_ray_parity.hpp) instead of the classifier.
  bool float_rays = false;
  bool space_cells = true;  ///< exact labels of the cells no face reaches (classifier.hpp)
  /// About how many points will be classified (from the points file's size), which sizes
  /// the space cells to the work; nullopt: unknown (standard input, a slice).
  std::optional<std::size_t> expected_points = std::nullopt;
  /// Look for faces that intersect (exactly): by default only where the labels are the
  /// parity solid's (--rule parity, faces not oriented alike, the float ray baseline),
  /// which the check then warns of; intersections change no winding number.
  SelfIntersectionCheck self_intersection_check = SelfIntersectionCheck::under_parity;
  unsigned threads = 0;  ///< 0: one per hardware thread
};

/// The --method name of what classifies: "embree" for the float ray baseline, else the
/// arithmetic's name ("exact", "double", ...).
std::string_view method_name(const InsideMeshOptions& options) noexcept;

/// The classifier the options ask for: the exact one (in any arithmetic) or the float ray
/// baseline, which keeps no mesh of its own (a slice's outline needs it, so it is kept here).
struct InsideMesh {
  std::optional<inside::Classifier> classifier;
  std::optional<inside::FloatRayParity> float_rays;
  mesh::Mesh float_rays_mesh;
  double seconds = 0.0;  ///< checking the mesh and building the search structures
  /// The faces that intersect, exactly; nullopt when the check was skipped
  /// (--no-self-intersection-check).
  std::optional<mesh::SelfIntersections> self;
  /// The check's own time; it runs beside the build unless one thread was asked for.
  double self_intersection_seconds = 0.0;

  const mesh::Mesh& mesh() const { return classifier ? classifier->mesh() : float_rays_mesh; }

  /// Labels `points` on `threads` threads (0: all), the classifier's signs in `arithmetic`;
  /// the float ray baseline has no arithmetic to choose.
  void classify(std::span<const Point3> points, std::span<inside::Location> locations,
                Arithmetic arithmetic, unsigned threads) const {
    if (float_rays) {
      inside::classify_batch(*float_rays, points, locations, threads);
    } else {
      inside::classify_batch(*classifier, points, locations, arithmetic, threads);
    }
  }

  /// The winding numbers of `points` (nullopt on the surface). The classifier only, on
  /// an oriented mesh (inside::winding_number_batch).
  void winding_numbers(std::span<const Point3> points,
                       std::span<std::optional<std::int64_t>> windings, Arithmetic arithmetic,
                       unsigned threads) const {
    inside::winding_number_batch(*classifier, points, windings, arithmetic, threads);
  }

  /// The generalized winding numbers of `points` as certified bounds (nullopt on the
  /// surface). The classifier only (inside::generalized_winding_number_batch).
  void generalized_winding_numbers(std::span<const Point3> points,
                                   std::span<std::optional<Enclosure>> bounds,
                                   Arithmetic arithmetic, unsigned threads) const {
    inside::generalized_winding_number_batch(*classifier, points, bounds, arithmetic, threads);
  }
};

/// Loads the mesh, builds its classifier and (unless the options skip it) looks for faces
/// that intersect: on such a mesh, by the parity rule, a warning on `err` says that the
/// labels are those of the parity solid (the winding rules label overlapping parts for
/// what they are, and say nothing). nullopt once an error is on `err` ("exactgeo inside: ...").
/// `progress`, when given, shows each task.
std::optional<InsideMesh> build_inside_mesh(const InsideMeshOptions& options, std::ostream& err,
                                            ProgressLine* progress = nullptr);

}  // namespace exactgeo::cli
