#pragma once

// An inexact baseline for point-in-volume classification, built to be measured against
// the exact Classifier; the exact classifier never uses it.
//
// It does what float ray-casting tools do (trimesh's `contains`, Open3D's occupancy):
// Embree's own float geometry, one float ray per point, every hit counted, odd count
// inside, even count outside. Quads are Embree's native quads and triangles its native
// triangles, with vertices rounded to float; the scene is built with Embree's defaults
// and RTC_SCENE_FLAG_ROBUST (as Open3D does). One departure from those tools, which
// convert raw coordinates to float: vertices and points are first mapped by the
// translation and power-of-two scaling of internal/float_frame.hpp (the frame the exact
// classifier's candidate search uses), so a mesh at 2^1000 or 2^-1000 neither overflows
// nor underflows float and gets the labels it gets at scale 1.
//
// What it gets wrong, by design:
// - A ray through a shared edge or vertex hits both faces there, or neither, depending on
//   the float arithmetic of Embree's triangle test, so the count can be off by one (or
//   more) and the label flipped. Nothing detects the degenerate ray or casts another.
// - Float rounding: vertices and the point are rounded to float in the frame (each
//   coordinate moves by up to about 2^-22 of the box's half-extent), so points that close
//   to the surface can land on either side of it.
// - Quads are not bilinear patches: Embree splits quad (v0, v1, v2, v3) into the
//   triangles v0 v1 v3 and v2 v3 v1, one of the two triangulations, which is a different
//   solid from the patch for a non-planar quad. The diagonal v1-v3 is one more edge to
//   graze: a ray through it is usually reported by both triangles (the filter sees the
//   same quad twice), so the quad counts twice.
// - There is no boundary label: a point on the surface is called inside or outside.
//
// The ray has direction ray_direction(0) = (1, 3/16, 9/256), exact in float, from the
// point rounded to float in the frame, tnear 0, tfar infinity. Points strictly outside
// the box of the faces' corners are outside without a ray, as in the exact classifier.

#include <memory>

#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::inside {

class FloatRayParity {
 public:
  /// Builds one Embree scene with a quad geometry for the quads and a triangle geometry
  /// for the triangles. The mesh need not be checked or closed (labels of an open mesh
  /// mean little), but every corner index must be in range (std::invalid_argument
  /// otherwise) and coordinates finite. Throws std::runtime_error if Embree fails.
  explicit FloatRayParity(const mesh::Mesh& mesh);
  ~FloatRayParity();
  FloatRayParity(FloatRayParity&&) noexcept;
  FloatRayParity& operator=(FloatRayParity&&) noexcept;
  FloatRayParity(const FloatRayParity&) = delete;
  FloatRayParity& operator=(const FloatRayParity&) = delete;

  /// Location::inside or Location::outside (never boundary), by the parity of the float
  /// ray's hits. Thread-safe.
  Location classify(const Point3& point) const;

 private:
  struct Scene;
  std::unique_ptr<Scene> scene_;
};

}  // namespace exactgeo::inside
