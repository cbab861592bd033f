#include "cli/inside_mesh.hpp"

#include <exception>
#include <future>
#include <ostream>
#include <stdexcept>
#include <string>

#include "cli/seconds.hpp"
#include "exactgeo/inside/self_intersection_warning.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/mesh/weld.hpp"

namespace exactgeo::cli {

using io::InputError;
using mesh::load_mesh;
using mesh::LoadedMesh;

namespace {

/// A mesh refused by its checks, explained: the checks' message in the file's own
/// numbering (OBJ counts vertices and faces from 1, OFF and PLY from 0), saying which, and
/// whether merging the vertices that repeat another's coordinates (--weld) would make it
/// acceptable. `message` as it is when the refusal was not the checks'. Only on this error
/// path is a file read a second time; standard input cannot be, so `kept` is the copy of
/// it taken before the build.
std::string refusal_explained(const InsideMeshOptions& options, const std::string& message,
                              const std::optional<LoadedMesh>& kept) {
  try {
    const LoadedMesh loaded = kept ? *kept : load_mesh(options.path, options.load);
    // The rule that was applied (the float ray baseline counts parity).
    const inside::FillRule rule =
        options.float_rays ? inside::FillRule::parity
                           : inside::rule_for(mesh::check_mesh(loaded.mesh), options.rule);
    // The float ray baseline takes no rule: it offers none.
    inside::OptionNames names = inside::kCommandLineNames;
    if (options.float_rays) names.parity = names.nonzero = "";
    return inside::refusal(loaded, rule, options.allow_non_manifold, names).value_or(message);
  } catch (const std::exception&) {
    return message;
  }
}

struct TimedCheck {
  mesh::SelfIntersections found;
  double seconds = 0.0;
};

TimedCheck check_self_intersections(const mesh::Mesh& mesh, unsigned threads) {
  const Clock::time_point start = Clock::now();
  TimedCheck check{mesh::find_self_intersections(mesh, threads), 0.0};
  check.seconds = seconds_since(start);
  return check;
}

}  // namespace

std::string_view method_name(const InsideMeshOptions& options) noexcept {
  return options.float_rays ? std::string_view("embree") : to_string(options.arithmetic);
}

std::optional<InsideMesh> build_inside_mesh(const InsideMeshOptions& options, std::ostream& err,
                                            ProgressLine* progress) {
  InsideMesh built;
  mesh::FileNumbering numbering;
  // The self-intersection check runs beside the build, which keeps one core busy, on a
  // copy of the mesh (the build takes the original), on the threads asked for; with one
  // thread asked for, after the build, on a copy all the same: the classifier's mesh lacks
  // the faces of zero area, and the pairs must be named by the file's face numbers. By
  // default it runs only where the labels will be the parity solid's; where the rule is
  // not given, that is known after the build (faces not oriented alike), so the faces are
  // kept for it (the classifier keeps every vertex).
  const bool parity_asked = options.float_rays || options.rule == inside::FillRule::parity;
  const bool check_now =
      options.self_intersection_check == SelfIntersectionCheck::always ||
      (options.self_intersection_check == SelfIntersectionCheck::under_parity && parity_asked);
  const bool check_if_parity =
      options.self_intersection_check == SelfIntersectionCheck::under_parity && !options.rule &&
      !options.float_rays;
  std::future<TimedCheck> beside;
  std::optional<mesh::Mesh> check_after;
  std::vector<mesh::Face> faces_as_read;
  const std::string source = mesh::mesh_source_name(options.path);
  std::optional<LoadedMesh> kept;
  try {
    if (progress) progress->task("reading " + source);
    LoadedMesh loaded = load_mesh(options.path, options.load);
    numbering = loaded.numbering;
    for (const std::string& note : loaded.notes) {
      if (progress) progress->clear();
      err << "exactgeo inside: warning: " << note << "\n";
    }
    if (options.path == "-") kept = loaded;  // to explain a refusal: it cannot be read again
    if (check_now && options.threads != 1) {
      beside = std::async(std::launch::async, [copy = loaded.mesh, threads = options.threads] {
        return check_self_intersections(copy, threads);
      });
    } else if (check_now) {
      check_after = loaded.mesh;
    } else if (check_if_parity) {
      faces_as_read = loaded.mesh.faces;
    }
    if (progress) {
      progress->task("building the search structure (" + grouped(loaded.mesh.faces.size()) +
                     " faces)" + (beside.valid() ? " and looking for faces that intersect" : ""));
    }
    const Clock::time_point start = Clock::now();
    if (options.float_rays) {
      // The same meshes as the classifier accepts, so that the two are compared on them.
      const mesh::MeshCheck check = mesh::check_mesh(loaded.mesh);
      if (auto problem =
              inside::rule_problem(check, inside::FillRule::parity, options.allow_non_manifold)) {
        throw std::invalid_argument(*problem);
      }
      built.float_rays.emplace(loaded.mesh);
      built.float_rays_mesh = std::move(loaded.mesh);
    } else {
      if (auto problem =
              inside::face_soup_problem(loaded, options.rule, inside::kCommandLineNames)) {
        throw std::invalid_argument(*problem);
      }
      inside::ClassifierOptions classifier_options;
      classifier_options.rule = options.rule;
      classifier_options.allow_non_manifold = options.allow_non_manifold;
      // The plain double baseline casts a ray for every point (classifier.hpp).
      classifier_options.space_cells =
          options.space_cells && options.arithmetic != Arithmetic::plain_double;
      classifier_options.expected_points = options.expected_points;
      built.classifier.emplace(std::move(loaded.mesh), classifier_options);
    }
    built.seconds = seconds_since(start);
    if (built.classifier) {
      if (const auto note = mesh::zero_area_note(built.classifier->zero_area_faces(), numbering)) {
        if (progress) progress->clear();
        err << "exactgeo inside: note: " << source << ": " << *note << "\n";
      }
    }
    if (const auto note = built.classifier ? built.classifier->open_note() : std::nullopt) {
      if (progress) progress->clear();
      err << "exactgeo inside: note: " << source << ": " << *note << "\n";
    } else if (built.classifier && !options.rule && !built.classifier->oriented()) {
      if (progress) progress->clear();
      err << "exactgeo inside: warning: " << source
          << ": the faces are not oriented alike (some edge is used more often in one direction "
             "than in the other), so they have no winding numbers: labelled by crossing parity "
             "(--rule parity)\n";
    }
  } catch (const InputError& e) {
    err << "exactgeo inside: " << e.what() << "\n";
    return std::nullopt;
  } catch (const std::invalid_argument& e) {
    err << "exactgeo inside: " << source << ": " << refusal_explained(options, e.what(), kept)
        << "\n";
    return std::nullopt;
  } catch (const std::exception& e) {  // Embree failing, or memory running out
    err << "exactgeo inside: " << source << ": cannot build the search structure: " << e.what()
        << "\n";
    return std::nullopt;
  }
  // Intersections change labels by parity only (the float ray baseline counts parity).
  const bool parity = options.float_rays || built.classifier->rule() == inside::FillRule::parity;
  if (!check_now && check_if_parity && parity) {
    check_after = mesh::Mesh{built.mesh().vertices, std::move(faces_as_read)};
  }
  if (beside.valid() || check_after) {
    if (progress && !beside.valid()) progress->task("looking for faces that intersect");
    TimedCheck check;
    try {
      check = beside.valid() ? beside.get() : check_self_intersections(*check_after, 1);
    } catch (const std::exception& e) {  // memory or threads running out
      err << "exactgeo inside: " << source << ": cannot look for faces that intersect: " << e.what()
          << "\n";
      return std::nullopt;
    }
    built.self = std::move(check.found);
    built.self_intersection_seconds = check.seconds;
    if (parity) {
      const bool oriented = built.classifier && built.classifier->oriented();
      for (const std::string& warning : inside::self_intersection_warnings(
               *built.self, numbering, oriented, inside::kCommandLineNames)) {
        if (progress) progress->clear();
        err << "exactgeo inside: warning: " << source << ": " << warning << "\n";
      }
    }
  }
  return built;
}

}  // namespace exactgeo::cli
