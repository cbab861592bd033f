#pragma once

// The mesh an `inside` run classifies against: loaded (with --format, --weld,
// --split-polygons), checked, and its search structure built, for the exact classifier (in
// any arithmetic) or the float ray baseline. A refused mesh is explained in the file's own
// numbering, with a hint when --weld would make it acceptable.

#include <iosfwd>
#include <optional>
#include <span>

#include "cli/inside_command.hpp"
#include "cli/progress_line.hpp"
#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/float_ray_parity.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/mesh/self_intersection.hpp"

namespace exactgeo::cli {

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

  void classify(std::span<const Point3> points, std::span<inside::Location> locations,
                const InsideCommandOptions& options) const {
    if (float_rays) {
      inside::classify_batch(*float_rays, points, locations, options.threads);
    } else {
      inside::classify_batch(*classifier, points, locations, options.arithmetic, options.threads);
    }
  }
};

/// Loads the mesh, builds its classifier and (unless the options skip it) looks for faces
/// that intersect: on such a mesh a warning on `err` says that the labels are those of
/// the parity solid. nullopt once an error is on `err` ("exactgeo inside: ..."). `progress`,
/// when given, shows each phase.
std::optional<InsideMesh> build_inside_mesh(const InsideCommandOptions& options, std::ostream& err,
                                            ProgressLine* progress = nullptr);

}  // namespace exactgeo::cli
