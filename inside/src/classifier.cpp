#include "exactgeo/inside/classifier.hpp"

#include <optional>
#include <stdexcept>

#include "exactgeo/inside/internal/candidates.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/crossing.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"

namespace exactgeo::inside {
namespace {

/// Directions the sequence has before they stop being exact in double (t_k^2 needs
/// (2k + 3)^2 < 2^53). For exact arithmetic the loop ends long before: at most
/// V + 2 (E + F) directions are degenerate (ray_directions.hpp), fewer than 2^25 for any
/// mesh below about four million faces.
constexpr std::size_t kExactDirections = std::size_t{1} << 25;
/// Plain double signs can call every ray degenerate; after this many it counts anyway.
constexpr std::size_t kPlainDoubleDirections = 64;

Crossing cross(const mesh::Mesh& mesh, const mesh::Face& face, const Point3& origin,
               const Vector3& direction, Arithmetic arithmetic) noexcept {
  if (face.is_triangle()) {
    const auto& v = mesh.vertices;
    return crossing_of(classify_ray_triangle(origin, direction, v[face.corners[0]],
                                             v[face.corners[1]], v[face.corners[2]], arithmetic)
                           .kind);
  }
  return crossing_of(ray_patch_parity(origin, direction, mesh::patch_of(mesh, face), arithmetic));
}

bool strictly_outside(const mesh::Box& box, const Point3& p) noexcept {
  for (int i = 0; i < 3; ++i) {
    if (p[i] < box.lower[i] || p[i] > box.upper[i]) return true;
  }
  return false;
}

}  // namespace

std::string_view to_string(Location location) noexcept {
  switch (location) {
    case Location::outside:
      return "outside";
    case Location::inside:
      return "inside";
    case Location::boundary:
      return "boundary";
  }
  return "?";
}

struct Classifier::State {
  mesh::Mesh mesh;
  mesh::Box box;
  std::optional<internal::EmbreeCandidates> embree;
};

Classifier::Classifier(mesh::Mesh mesh, ClassifierOptions options)
    : state_(std::make_unique<State>()) {
  const mesh::MeshCheck check = mesh::check_mesh(mesh);
  if (auto problem = mesh::closed_surface_problem(check, options.allow_non_manifold)) {
    throw std::invalid_argument(*problem);
  }
  state_->box = *check.bounding_box;
  state_->mesh = std::move(mesh);
  if (options.candidates == CandidateSearch::embree) state_->embree.emplace(state_->mesh);
}

Classifier::~Classifier() = default;
Classifier::Classifier(Classifier&&) noexcept = default;
Classifier& Classifier::operator=(Classifier&&) noexcept = default;

const mesh::Mesh& Classifier::mesh() const noexcept {
  return state_->mesh;
}

Location Classifier::classify(const Point3& point, Arithmetic arithmetic) const {
  ClassifierScratch scratch;
  return classify(point, arithmetic, scratch);
}

Location Classifier::classify(const Point3& point, Arithmetic arithmetic,
                              ClassifierScratch& scratch) const {
  // The solid lies in the convex hull of its surface, hence in the box.
  if (strictly_outside(state_->box, point)) return Location::outside;

  const mesh::Mesh& mesh = state_->mesh;
  const bool exact = arithmetic != Arithmetic::plain_double;
  const std::size_t directions = exact ? kExactDirections : kPlainDoubleDirections;
  bool odd = false;
  for (std::size_t k = 0; k < directions; ++k) {
    if (state_->embree && k < kFloatExactRayDirections) {
      state_->embree->find(point, k, scratch.candidates);
    } else {
      internal::all_faces(mesh, scratch.candidates);
    }
    const Vector3 direction = ray_direction(k);
    odd = false;
    bool clean = true;
    for (const internal::FaceIndex f : scratch.candidates) {
      const Crossing c = cross(mesh, mesh.faces[f], point, direction, arithmetic);
      if (c == Crossing::origin_on) return Location::boundary;
      if (c == Crossing::ambiguous) {
        clean = false;
        if (exact) break;  // plain double may keep counting: it may never see a clean ray
      }
      if (c == Crossing::crossed) odd = !odd;
    }
    if (clean) return odd ? Location::inside : Location::outside;
  }
  // Plain double only (see kExactDirections): the last ray's count, degenerate faces
  // counted as not crossed.
  return odd ? Location::inside : Location::outside;
}

}  // namespace exactgeo::inside
