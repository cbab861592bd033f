#pragma once

// The cloth remesher's floating-point shortcuts: cheaper forms of its float decisions (an
// angle against the quality floor, a length against a limit, a curvature ask against the
// largest size, two opposite angles' sum against a half turn) that give the answer of the
// full computation wherever they give one. They are not exact predicates and need not be:
// the remesher's choices are policy, and every operation it proposes is checked exactly
// by the library. Each shortcut compares squares or products with a relative margin far
// beyond the few ulps by which they and the full computation's hypot, atan2 and division
// round apart, and declines (nullopt, false, or the full computation) where they may have
// lost their precision (below 1e-280, or not finite). Tested against the full
// computations on random inputs and on inputs a relative 1e-16 to 1e-5 from each limit
// (tests/examples/float_shortcuts_test.cpp).

#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::cloth {

/// The quality guard, in the world (where the simulation and the picture see the
/// triangles): no operation makes a triangle whose smallest angle is below this, unless
/// the triangles it replaces were worse already (it may improve a sliver, never make one).
/// El Topo's default floor is 3 degrees; slivers here sat at the tips of the cones the
/// folds buckle into, which a finer floor keeps from forming where the remesher acts.
inline constexpr double kMinAngle = 5.0 * std::numbers::pi / 180.0;

/// The smallest angle of the triangle p q r (0 for a degenerate one).
double world_min_angle(const Point3& p, const Point3& q, const Point3& r);

/// world_min_angle, with kMinAngle standing for any angle clearly above it: every corner's
/// sides u and v have |u x v|^2 >= (1 + 1e-6) tan^2(kMinAngle) (u . v)^2, or u . v <= 0
/// with u x v not zero (an angle of at least a right angle). The guard compares a new
/// triangle's angle only with kMinAngle, and with the old triangles' only when it is
/// below kMinAngle (where an old angle clear of the floor is above it, and so is kMinAngle
/// standing for it), so its answers are those of world_min_angle; most triangles are
/// clear of the floor and need no atan2.
double world_min_angle_to_floor(const Point3& p, const Point3& q, const Point3& r);

/// Whether hypot(dx, dy) > limit, decided by the squares when they are a relative 1e-9
/// apart; nullopt otherwise (then hypot decides). Inline: the collapse candidates' shape
/// check asks it of every edge a collapse would make, millions of times a run.
inline std::optional<bool> clearly_longer(double dx, double dy, double limit) {
  constexpr double kMargin = 1e-9;
  constexpr double kTiny = 1e-280;  // as float_shortcuts.cpp's: below, squares lose precision
  const auto usable = [](double square) { return square > kTiny && std::isfinite(square); };
  const double squared = dx * dx + dy * dy, limit_squared = limit * limit;
  if (!usable(squared) || !usable(limit_squared)) return std::nullopt;
  if (squared > (1.0 + kMargin) * limit_squared) return true;
  if (squared < (1.0 - kMargin) * limit_squared) return false;
  return std::nullopt;
}

/// Whether an edge whose triangles' normals have cross product `c` and dot product `dot`,
/// and whose material length squared is `length_squared`, surely asks for a size of at
/// least `max_length` (the ask is length * turn_per_edge / angle, the angle between the
/// normals atan2(|c|, dot)): the angle is at most its tangent |c| / dot for dot > 0, so
/// |c|^2 max_length^2 below length^2 turn^2 dot^2 by a relative 1e-6 puts the ask above
/// max_length. False means: work it out. Inline, as clearly_longer: the sizes ask it of
/// every inner sheet edge at each remesh's start.
inline bool asks_no_less_than_max(const std::array<double, 3>& c, double dot, double length_squared,
                                  double max_length, double turn_per_edge) {
  constexpr double kMargin = 1.0 + 1e-6;
  constexpr double kTiny = 1e-280;  // as float_shortcuts.cpp's: below, squares lose precision
  const auto usable = [](double square) { return square > kTiny && std::isfinite(square); };
  if (!(dot > 0.0)) return false;
  const double cross_squared = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
  const double lhs = cross_squared * (max_length * max_length);
  const double rhs = length_squared * (turn_per_edge * turn_per_edge) * (dot * dot);
  return usable(cross_squared) && usable(dot * dot) && usable(length_squared) && usable(lhs) &&
         usable(rhs) && kMargin * lhs < rhs;
}

/// Whether two angles, atan2(cross1, dot1) + atan2(cross2, dot2) (cross1, cross2 >= 0: each
/// in [0, pi], a corner's of a triangle, from its sides' cross and dot products), sum to
/// more than pi + slack (slack >= 0, below a quarter turn; given as tan_slack = tan(slack),
/// which a caller asking for many edges works out once), decided without atan2 where it is
/// clear; nullopt otherwise (then atan2 decides). The sum less pi is the angle theta of
/// (-s, -c), s = cross1 dot2 + dot1 cross2 and c = dot1 dot2 - cross1 cross2 (N sin and N
/// cos of the sum, N the four sides' lengths' product): for c < 0, theta is within a
/// quarter turn of 0 and theta - slack has the sign of t c - s (N sin(theta - slack) /
/// cos(slack), t = tan(slack)); for c >= 0, theta is at least a quarter turn from 0 and
/// has the sign of -s. Either is taken only when it exceeds 1e-9 m, m = (cross1 + |dot1|)
/// (cross2 + |dot2|) >= N: then theta lies at least 1e-9 from slack, far beyond the few
/// ulps by which the products and the full computation's atan2 round. Inline: the flip
/// candidates ask it of every inner sheet edge in a remesh's first flip pass.
inline std::optional<bool> clearly_beyond_half_turn(double cross1, double dot1, double cross2,
                                                    double dot2, double tan_slack) {
  constexpr double kMargin = 1e-9;
  constexpr double kTiny = 1e-280;  // as float_shortcuts.cpp's: below, squares lose precision
  const auto usable = [](double square) { return square > kTiny && std::isfinite(square); };
  const double m = (cross1 + std::abs(dot1)) * (cross2 + std::abs(dot2));
  if (!(cross1 >= 0.0) || !(cross2 >= 0.0) || !usable(m)) return std::nullopt;
  const double s = cross1 * dot2 + dot1 * cross2;  // N sin(alpha + beta)
  const double c = dot1 * dot2 - cross1 * cross2;  // N cos(alpha + beta)
  const double margin = kMargin * m;
  const double beyond = c < 0.0 ? tan_slack * c - s : -s;
  if (beyond > margin) return true;
  if (beyond < -margin) return false;
  return std::nullopt;
}

}  // namespace exactgeo::cloth
