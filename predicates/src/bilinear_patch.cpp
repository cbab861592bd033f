#include "exactgeo/predicates/bilinear_patch.hpp"

#include <algorithm>

#include "exactgeo/predicates/internal/patch_span.hpp"

namespace exactgeo {

using kernel::Offset;

std::string_view to_string(PatchShape shape) noexcept {
  switch (shape) {
    case PatchShape::skew:
      return "skew";
    case PatchShape::convex:
      return "convex";
    case PatchShape::concave:
      return "concave";
    case PatchShape::butterfly:
      return "butterfly";
    case PatchShape::degenerate_planar:
      return "degenerate-planar";
    case PatchShape::segment:
      return "segment";
    case PatchShape::point:
      return "point";
  }
  return "skew";
}

std::string_view to_string(RayPatch r) noexcept {
  switch (r) {
    case RayPatch::even:
      return "even";
    case RayPatch::odd:
      return "odd";
    case RayPatch::origin_on_patch:
      return "on";
    case RayPatch::degenerate:
      return "degenerate";
  }
  return "degenerate";
}

PatchShape classify_patch(const BilinearPatch& patch) noexcept {
  const kernel::ExactSigns signs;
  const auto x = internal::tensor_corners(patch);
  const PatchSpan span = internal::patch_span(signs, x);
  switch (span.kind) {
    case PatchSpan::Kind::skew:
      return PatchShape::skew;
    case PatchSpan::Kind::collinear:
      return x[0] == x[1] && x[0] == x[2] && x[0] == x[3] ? PatchShape::point : PatchShape::segment;
    case PatchSpan::Kind::planar:
      break;
  }
  const int k = *internal::normal_axis(signs, x, span.plane_triple);
  // The turn at each corner of the boundary polygon x0 -> x1 -> x3 -> x2.
  auto turn = [&](int prev, int at, int next) {
    return signs.cross2(k, Offset::between(x[prev], x[at]), Offset::between(x[prev], x[next]));
  };
  const std::array<Sign, 4> turns{turn(0, 1, 3), turn(1, 3, 2), turn(3, 2, 0), turn(2, 0, 1)};
  if (std::count(turns.begin(), turns.end(), Sign::zero) > 0) return PatchShape::degenerate_planar;
  const auto positive = std::count(turns.begin(), turns.end(), Sign::positive);
  if (positive == 4 || positive == 0) return PatchShape::convex;
  if (positive == 2) return PatchShape::butterfly;
  return PatchShape::concave;
}

RayPatchCrossings ray_patch_crossings(const Point3& origin, const Vector3& direction,
                                      const BilinearPatch& patch, Arithmetic arithmetic) noexcept {
  const auto x = internal::tensor_corners(patch);
  return kernel::with_signs(arithmetic, [&](const auto& signs) {
    return internal::ray_patch_crossings_offsets(signs, internal::patch_span(signs, x),
                                                 internal::offsets_from(origin, x),
                                                 Offset::vector(direction));
  });
}

RayPatch ray_patch_parity(const Point3& origin, const Vector3& direction,
                          const BilinearPatch& patch, Arithmetic arithmetic) noexcept {
  return ray_patch_crossings(origin, direction, patch, arithmetic).parity;
}

Sign patch_side(const BilinearPatch& patch, const Point3& x, Arithmetic arithmetic) noexcept {
  const auto corners = internal::tensor_corners(patch);
  return kernel::with_signs(
      arithmetic, [&](const auto& signs) { return signs.phi(internal::offsets_from(x, corners)); });
}

}  // namespace exactgeo
