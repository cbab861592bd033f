#pragma once

// The input representation of every predicate: vectors given exactly as the difference
// of two double points, head - tail. A plain vector d is d - 0; a corner relative to a ray
// origin is corner - origin; a continuous-collision corner is x_i(t) - y_j(t) (origin 0).
//
// An Offset refers to its two points (it does not copy them): it is a view, valid while
// the points live, and cheap to pass around the predicates' hot path. Building one from a
// temporary point does not compile.
//
// An Offset can also view an ExactVector (exact_vector.hpp): head = its rounded value,
// tail = a zero point reserved for that purpose. The filter treats both kinds alike; the
// exact stages and the exact equality tests below tell them apart.

#include <array>
#include <cstddef>

#include "exactgeo/predicates/kernel/exact_vector.hpp"
#include "exactgeo/predicates/kernel/formulas.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::kernel {

inline constexpr Point3 kZeroPoint{0.0, 0.0, 0.0};
/// The tail of every Offset that views an ExactVector (its address marks the kind).
inline constexpr Point3 kExactVectorTail{0.0, 0.0, 0.0};

class Offset {
 public:
  /// to - from
  static constexpr Offset between(const Point3& from, const Point3& to) noexcept {
    return Offset(&to, &from);
  }
  static Offset between(Point3&&, const Point3&) = delete;
  static Offset between(const Point3&, Point3&&) = delete;
  static Offset between(Point3&&, Point3&&) = delete;

  /// v - 0
  static constexpr Offset vector(const Vector3& v) noexcept { return Offset(&v, &kZeroPoint); }
  static Offset vector(Vector3&&) = delete;

  /// The exact vector v (rounded - 0 to the filter).
  static Offset exact(const ExactVector& v) noexcept {
    return Offset(&v.rounded, &kExactVectorTail);
  }
  static Offset exact(ExactVector&&) = delete;

  bool is_exact_vector() const noexcept { return tail_ == &kExactVectorTail; }
  /// Precondition: is_exact_vector().
  const ExactVector& exact_vector() const noexcept {
    return *reinterpret_cast<const ExactVector*>(head_);
  }

  /// Certainly the same vector (the converse need not hold): the same head and tail
  /// values, or two exact vectors with equal exact coordinates. An exact test.
  bool same_points_as(const Offset& other) const noexcept {
    if (is_exact_vector() || other.is_exact_vector()) {
      return is_exact_vector() && other.is_exact_vector() &&
             !certainly_different(exact_vector(), other.exact_vector()) &&
             exact_vector().exact == other.exact_vector().exact;
    }
    return *head_ == *other.head_ && *tail_ == *other.tail_;
  }
  const Point3& head_point() const noexcept { return *head_; }
  const Point3& tail_point() const noexcept { return *tail_; }

  double head(int axis) const noexcept { return (*head_)[axis]; }
  double tail(int axis) const noexcept { return (*tail_)[axis]; }

  /// fl(head - tail) per coordinate: |error| <= u |result| (zero exactly when the
  /// coordinate is zero; a difference of doubles never underflows to a wrong zero).
  Vec3<double> rounded() const noexcept {
    return {head(0) - tail(0), head(1) - tail(1), head(2) - tail(2)};
  }

 private:
  constexpr Offset(const Point3* head, const Point3* tail) noexcept : head_(head), tail_(tail) {}

  const Point3* head_;
  const Point3* tail_;
};

template <std::size_t N>
using Offsets = std::array<Offset, N>;

}  // namespace exactgeo::kernel
