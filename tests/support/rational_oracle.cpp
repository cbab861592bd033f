#include "support/rational_oracle.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace exactgeo::testing {
namespace {

using Rational = mpq_class;

// ---------------------------------------------------------------------------------------
// Rational 3-vectors.

using Vec3 = std::array<Rational, 3>;

Vec3 exact(const Point3& p) {
  for (const double x : p) {
    if (!std::isfinite(x)) throw std::invalid_argument("rational oracle: non-finite coordinate");
  }
  return {Rational(p[0]), Rational(p[1]), Rational(p[2])};
}

Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 operator*(const Rational& k, const Vec3& a) {
  return {k * a[0], k * a[1], k * a[2]};
}

Rational dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// det[a, b, c] with a, b, c as columns (or rows).
Rational det(const Vec3& a, const Vec3& b, const Vec3& c) {
  return dot(a, cross(b, c));
}

bool is_zero(const Vec3& a) {
  return a[0] == 0 && a[1] == 0 && a[2] == 0;
}

Sign sign_of(const Rational& x) {
  return static_cast<Sign>(sgn(x));
}

// ---------------------------------------------------------------------------------------
// Linear systems over Q.

/// A dense rational matrix, stored by rows.
using Matrix = std::vector<std::vector<Rational>>;

/// The 3 x n matrix with the given columns.
Matrix from_columns(std::initializer_list<Vec3> columns) {
  Matrix m(3);
  for (const Vec3& column : columns) {
    for (std::size_t row = 0; row < 3; ++row) {
      m[row].push_back(column[row]);
    }
  }
  return m;
}

/// The n x 3 matrix with the given rows.
Matrix from_rows(std::initializer_list<Vec3> rows) {
  Matrix m;
  for (const Vec3& row : rows) {
    m.push_back({row[0], row[1], row[2]});
  }
  return m;
}

/// Gauss-Jordan elimination of `m` in place, choosing pivots among its first
/// `pivot_column_count` columns (the others, e.g. a right-hand side, are carried along).
/// Returns the pivot column of each nonzero row, in row order; the rank is their number.
std::vector<std::size_t> reduce_to_echelon_form(Matrix& m, std::size_t pivot_column_count) {
  std::vector<std::size_t> pivots;
  std::size_t row = 0;
  for (std::size_t col = 0; col < pivot_column_count && row < m.size(); ++col) {
    std::size_t pivot_row = row;
    while (pivot_row < m.size() && m[pivot_row][col] == 0) {
      ++pivot_row;
    }
    if (pivot_row == m.size()) continue;
    std::swap(m[row], m[pivot_row]);
    const Rational pivot = m[row][col];
    for (Rational& x : m[row]) {
      x /= pivot;
    }
    for (std::size_t other = 0; other < m.size(); ++other) {
      if (other == row || m[other][col] == 0) continue;
      const Rational factor = m[other][col];
      for (std::size_t j = 0; j < m[other].size(); ++j) {
        m[other][j] -= factor * m[row][j];
      }
    }
    pivots.push_back(col);
    ++row;
  }
  return pivots;
}

std::size_t rank(Matrix m) {
  const std::size_t columns = m.empty() ? 0 : m.front().size();
  return reduce_to_echelon_form(m, columns).size();
}

/// An affine subspace {point + sum_k y_k directions[k]} of Q^n, in parametric form; the
/// directions are linearly independent.
struct AffineSet {
  std::vector<Rational> point;
  std::vector<std::vector<Rational>> directions;
};

/// All solutions x of a x = b, or nullopt when there are none.
std::optional<AffineSet> solve(const Matrix& a, const std::vector<Rational>& b) {
  const std::size_t n = a.front().size();
  Matrix augmented = a;
  for (std::size_t row = 0; row < augmented.size(); ++row) {
    augmented[row].push_back(b[row]);
  }
  const std::vector<std::size_t> pivots = reduce_to_echelon_form(augmented, n);
  for (std::size_t row = pivots.size(); row < augmented.size(); ++row) {
    if (augmented[row][n] != 0) return std::nullopt;  // 0 = nonzero
  }
  AffineSet set;
  set.point.assign(n, Rational(0));
  for (std::size_t r = 0; r < pivots.size(); ++r) {
    set.point[pivots[r]] = augmented[r][n];
  }
  for (std::size_t free = 0; free < n; ++free) {
    if (std::find(pivots.begin(), pivots.end(), free) != pivots.end()) continue;
    std::vector<Rational> direction(n, Rational(0));
    direction[free] = 1;
    for (std::size_t r = 0; r < pivots.size(); ++r) {
      direction[pivots[r]] = -augmented[r][free];
    }
    set.directions.push_back(std::move(direction));
  }
  return set;
}

std::optional<AffineSet> solve(const Matrix& a, const Vec3& b) {
  return solve(a, std::vector<Rational>{b[0], b[1], b[2]});
}

// ---------------------------------------------------------------------------------------
// Linear feasibility over Q (Fourier-Motzkin elimination).

/// An affine function c . y + constant of the parameters y of an AffineSet.
struct AffineFunction {
  std::vector<Rational> coefficients;
  Rational constant;
};

/// Coordinate i of the points of `set`, as a function of its parameters.
AffineFunction coordinate(const AffineSet& set, std::size_t i) {
  AffineFunction f{{}, set.point[i]};
  for (const std::vector<Rational>& direction : set.directions) {
    f.coefficients.push_back(direction[i]);
  }
  return f;
}

AffineFunction one_minus(AffineFunction f) {
  for (Rational& c : f.coefficients) {
    c = -c;
  }
  f.constant = 1 - f.constant;
  return f;
}

/// f > 0 when strict, f >= 0 otherwise.
struct Inequality {
  AffineFunction f;
  bool strict = false;
};

/// The combination of a lower bound (coefficient a > 0 on y_j) and an upper bound
/// (coefficient b < 0 on y_j) without y_j: (-b) lower + a upper, positive multipliers.
Inequality combine(const Inequality& lower, const Inequality& upper, std::size_t j) {
  const Rational a = lower.f.coefficients[j];
  const Rational minus_b = -upper.f.coefficients[j];
  Inequality sum{{{}, minus_b * lower.f.constant + a * upper.f.constant},
                 lower.strict || upper.strict};
  for (std::size_t k = 0; k < lower.f.coefficients.size(); ++k) {
    sum.f.coefficients.push_back(minus_b * lower.f.coefficients[k] + a * upper.f.coefficients[k]);
  }
  return sum;
}

/// Whether some real y satisfies every inequality. Fourier-Motzkin: y_j exists iff every
/// lower bound on it is below every upper bound (strictly if either bound is strict), so
/// replacing the bounds on y_j by their pairwise combinations describes exactly the
/// projection of the solution set; once every variable is gone, the constants decide.
bool is_feasible(std::vector<Inequality> system) {
  const std::size_t variable_count = system.empty() ? 0 : system.front().f.coefficients.size();
  for (std::size_t j = 0; j < variable_count; ++j) {
    std::vector<Inequality> lower, upper, next;
    for (Inequality& inequality : system) {
      const int s = sgn(inequality.f.coefficients[j]);
      (s > 0 ? lower : s < 0 ? upper : next).push_back(std::move(inequality));
    }
    for (const Inequality& l : lower) {
      for (const Inequality& u : upper) {
        next.push_back(combine(l, u, j));
      }
    }
    system = std::move(next);
  }
  return std::all_of(system.begin(), system.end(), [](const Inequality& inequality) {
    return inequality.strict ? inequality.f.constant > 0 : inequality.f.constant >= 0;
  });
}

// ---------------------------------------------------------------------------------------
// Convex hulls and segments.

enum class RayStart : std::uint8_t {
  closed,  ///< the ray is {o + s d : s >= 0}
  open,    ///< the ray is {o + s d : s > 0}
};

/// Whether origin + s direction lies in the convex hull of `points` for some admissible s:
/// feasibility of sum_i w_i P_i - s d = o, sum_i w_i = 1, w_i >= 0, s >= 0 (or > 0).
bool ray_meets_hull(const Vec3& origin, const Vec3& direction, const std::vector<Vec3>& points,
                    RayStart start) {
  const std::size_t m = points.size();  // unknowns: w_0 .. w_{m-1}, then s
  Matrix a(4, std::vector<Rational>(m + 1));
  std::vector<Rational> b(4);
  for (std::size_t k = 0; k < 3; ++k) {
    for (std::size_t i = 0; i < m; ++i) {
      a[k][i] = points[i][k];
    }
    a[k][m] = -direction[k];
    b[k] = origin[k];
  }
  for (std::size_t i = 0; i < m; ++i) {
    a[3][i] = 1;
  }
  b[3] = 1;
  const std::optional<AffineSet> set = solve(a, b);
  if (!set) return false;
  std::vector<Inequality> constraints;
  for (std::size_t i = 0; i < m; ++i) {
    constraints.push_back({coordinate(*set, i), false});
  }
  constraints.push_back({coordinate(*set, m), start == RayStart::open});
  return is_feasible(std::move(constraints));
}

bool hull_contains(const std::vector<Vec3>& points, const Vec3& x) {
  // The ray with zero direction is the point x itself.
  return ray_meets_hull(x, Vec3{0, 0, 0}, points, RayStart::closed);
}

/// Whether the closed segments [a, b] and [c, d] share a point:
/// a + l (b - a) = c + m (d - c) with l, m in [0, 1].
bool segments_intersect(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const std::optional<AffineSet> set = solve(from_columns({b - a, c - d}), c - a);
  if (!set) return false;
  std::vector<Inequality> constraints;
  for (std::size_t i = 0; i < 2; ++i) {
    constraints.push_back({coordinate(*set, i), false});
    constraints.push_back({one_minus(coordinate(*set, i)), false});
  }
  return is_feasible(std::move(constraints));
}

// ---------------------------------------------------------------------------------------
// Q(sqrt r): exact arithmetic on the roots of rational quadratics.

/// The real number x + y sqrt(r), with rationals x, y and a radicand r >= 0 shared by all
/// the numbers of one computation.
class QuadraticSurd {
 public:
  QuadraticSurd(Rational x, Rational y, Rational r)
      : x_(std::move(x)), y_(std::move(y)), r_(std::move(r)) {
    if (r_ < 0) throw std::logic_error("QuadraticSurd: negative radicand");
  }

  friend QuadraticSurd operator+(const Rational& a, const QuadraticSurd& z) {
    return {a + z.x_, z.y_, z.r_};
  }
  friend QuadraticSurd operator*(const Rational& a, const QuadraticSurd& z) {
    return {a * z.x_, a * z.y_, z.r_};
  }
  /// Both numbers must be in the same field Q(sqrt r) (or one of them rational).
  friend QuadraticSurd operator+(const QuadraticSurd& a, const QuadraticSurd& b) {
    if (a.y_ == 0) return a.x_ + b;
    if (b.y_ == 0) return b.x_ + a;
    if (a.r_ != b.r_) throw std::logic_error("QuadraticSurd: sum across two radicands");
    return {a.x_ + b.x_, a.y_ + b.y_, a.r_};
  }

  /// Exact sign: when x and y sqrt(r) have opposite signs, the larger of x^2 and y^2 r
  /// decides.
  Sign sign() const {
    const Sign sx = sign_of(x_);
    const Sign sy = r_ == 0 ? Sign::zero : sign_of(y_);
    if (sy == Sign::zero || sx == sy) return sx;
    if (sx == Sign::zero) return sy;
    const Sign x_dominates = sign_of(x_ * x_ - y_ * y_ * r_);
    if (x_dominates == Sign::zero) return Sign::zero;
    return x_dominates == Sign::positive ? sx : sy;
  }

 private:
  Rational x_, y_, r_;
};

/// c2 x^2 + c1 x + c0.
struct Quadratic {
  Rational c2, c1, c0;
  bool is_zero() const { return c2 == 0 && c1 == 0 && c0 == 0; }
};

struct Root {
  QuadraticSurd value;
  int multiplicity;
};

/// The real roots of q, which must not be the zero polynomial, with multiplicity.
std::vector<Root> real_roots(const Quadratic& q) {
  if (q.c2 == 0) {
    if (q.c1 == 0) return {};  // nonzero constant
    return {{QuadraticSurd(-q.c0 / q.c1, 0, 0), 1}};
  }
  const Rational discriminant = q.c1 * q.c1 - 4 * q.c2 * q.c0;
  const Rational centre = -q.c1 / (2 * q.c2);
  if (discriminant < 0) return {};
  if (discriminant == 0) return {{QuadraticSurd(centre, 0, 0), 2}};
  // (-c1 +- sqrt(disc)) / (2 c2)
  const Rational half_width = 1 / (2 * q.c2);
  return {{QuadraticSurd(centre, half_width, discriminant), 1},
          {QuadraticSurd(centre, -half_width, discriminant), 1}};
}

// ---------------------------------------------------------------------------------------
// Bilinear patches: p(u, v) = p00 + u e + v f + u v g.

struct ExactPatch {
  Vec3 p00, p10, p11, p01;

  Vec3 e() const { return p10 - p00; }
  Vec3 f() const { return p01 - p00; }
  Vec3 g() const { return p11 - p10 - p01 + p00; }
  /// The corners in boundary order p00 -> p10 -> p11 -> p01.
  std::vector<Vec3> corners() const { return {p00, p10, p11, p01}; }
};

ExactPatch exact(const BilinearPatch& patch) {
  return {exact(patch.p00), exact(patch.p10), exact(patch.p11), exact(patch.p01)};
}

// The unknowns of the linear systems below: u, v, t (standing for the product u v) and,
// for rays, s.
constexpr std::size_t kU = 0;
constexpr std::size_t kV = 1;
constexpr std::size_t kT = 2;
constexpr std::size_t kS = 3;

enum class Square : std::uint8_t { closed, open };

/// (u, v) in [0, 1]^2 (closed) or (0, 1)^2 (open), as constraints on the parameters of
/// `set`.
std::vector<Inequality> unit_square_constraints(const AffineSet& set, Square square) {
  const bool strict = square == Square::open;
  std::vector<Inequality> constraints;
  for (const std::size_t i : {kU, kV}) {
    constraints.push_back({coordinate(set, i), strict});
    constraints.push_back({one_minus(coordinate(set, i)), strict});
  }
  return constraints;
}

bool in_unit_interval(const QuadraticSurd& x, Square square) {
  const Sign low = x.sign();
  const Sign high = (Rational(-1) + x).sign();
  if (square == Square::open) return low == Sign::positive && high == Sign::negative;
  return low != Sign::negative && high != Sign::positive;
}

/// Along the line {point + l direction} of (u, v, t, ...) space, the surface condition
/// t = u v reads q(l) = 0.
Quadratic surface_condition_on_line(const AffineSet& line) {
  const std::vector<Rational>& p = line.point;
  const std::vector<Rational>& k = line.directions.front();
  return {-k[kU] * k[kV], k[kT] - p[kU] * k[kV] - k[kU] * p[kV], p[kT] - p[kU] * p[kV]};
}

QuadraticSurd coordinate_at(const AffineSet& line, std::size_t i, const QuadraticSurd& l) {
  return line.point[i] + line.directions.front()[i] * l;
}

/// Whether c0 + cu u + cv v + cuv u v vanishes somewhere on [0, 1]^2. The function is
/// affine in each variable, so its extremes over the square are at the corners; the square
/// is connected, so it has a zero iff its corner values are not all of one strict sign.
bool bilinear_vanishes_on_unit_square(const Rational& c0, const Rational& cu, const Rational& cv,
                                      const Rational& cuv) {
  const std::array<Rational, 4> corner_values{c0, c0 + cu, c0 + cv, c0 + cu + cv + cuv};
  const bool some_nonpositive = std::any_of(corner_values.begin(), corner_values.end(),
                                            [](const Rational& x) { return x <= 0; });
  const bool some_nonnegative = std::any_of(corner_values.begin(), corner_values.end(),
                                            [](const Rational& x) { return x >= 0; });
  return some_nonpositive && some_nonnegative;
}

/// Step (a): whether x = p(u, v) for some (u, v) in [0, 1]^2. Linearize with t = u v:
/// u e + v f + t g = x - p00 is a linear system in (u, v, t) whose solution set (a point,
/// a line, a plane or everything) is then intersected with the surface t = u v.
bool on_patch(const ExactPatch& patch, const Vec3& x) {
  const std::optional<AffineSet> set =
      solve(from_columns({patch.e(), patch.f(), patch.g()}), x - patch.p00);
  if (!set) return false;
  switch (set->directions.size()) {
    case 0: {
      const std::vector<Rational>& p = set->point;
      return p[kT] == p[kU] * p[kV] && p[kU] >= 0 && p[kU] <= 1 && p[kV] >= 0 && p[kV] <= 1;
    }
    case 1: {
      const Quadratic q = surface_condition_on_line(*set);
      if (q.is_zero()) {
        // The whole line lies on the surface: its (u, v) trace is a line of the uv plane.
        return is_feasible(unit_square_constraints(*set, Square::closed));
      }
      const std::vector<Root> roots = real_roots(q);
      return std::any_of(roots.begin(), roots.end(), [&](const Root& root) {
        return in_unit_interval(coordinate_at(*set, kU, root.value), Square::closed) &&
               in_unit_interval(coordinate_at(*set, kV, root.value), Square::closed);
      });
    }
    case 2: {
      // A plane n . (u, v, t) = n . point, with n normal to both directions; on t = u v it
      // is one bilinear equation in (u, v).
      const auto as_vec3 = [](const std::vector<Rational>& w) { return Vec3{w[0], w[1], w[2]}; };
      const Vec3 n = cross(as_vec3(set->directions[0]), as_vec3(set->directions[1]));
      return bilinear_vanishes_on_unit_square(-dot(n, as_vec3(set->point)), n[kU], n[kV], n[kT]);
    }
    default:
      return true;  // all corners equal x
  }
}

/// Step (b): whether the ray (s > 0) meets one of the four closed boundary segments.
bool ray_meets_boundary(const ExactPatch& patch, const Vec3& o, const Vec3& d) {
  const std::vector<Vec3> c = patch.corners();
  for (std::size_t i = 0; i < 4; ++i) {
    if (ray_meets_hull(o, d, {c[i], c[(i + 1) % 4]}, RayStart::open)) return true;
  }
  return false;
}

/// Whether the corners, o and o + d lie in one plane (affine rank <= 2).
bool ray_in_plane_of_corners(const ExactPatch& patch, const Vec3& o, const Vec3& d) {
  const Vec3& p00 = patch.p00;
  return rank(from_rows({patch.p10 - p00, patch.p11 - p00, patch.p01 - p00, o - p00, d})) <= 2;
}

/// Steps (a) to (c) of ray_patch_oracle; nullopt when the crossings must be counted.
std::optional<RayPatch> decide_without_counting(const ExactPatch& patch, const Vec3& o,
                                                const Vec3& d) {
  if (on_patch(patch, o)) return RayPatch::origin_on_patch;
  if (ray_meets_boundary(patch, o, d)) return RayPatch::degenerate;
  if (ray_in_plane_of_corners(patch, o, d) &&
      ray_meets_hull(o, d, patch.corners(), RayStart::open)) {
    return RayPatch::degenerate;
  }
  return std::nullopt;
}

/// The solutions of step (d), counted two ways.
struct CrossingCounts {
  int with_multiplicity = 0;
  /// Each solution counted as the sign of n . d, n = dp/du x dp/dv there.
  int signed_count = 0;
};

/// n(u, v) . d for the patch's normal n = dp/du x dp/dv = (e + v g) x (f + u g):
/// det[e, f, d] + u det[e, g, d] + v det[g, f, d] (the u v term has det[g, g, d] = 0).
Sign normal_dot_direction(const ExactPatch& patch, const Vec3& d, const QuadraticSurd& u,
                          const QuadraticSurd& v) {
  const Vec3 e = patch.e(), f = patch.f(), g = patch.g();
  return (det(e, f, d) + (det(e, g, d) * u + det(g, f, d) * v)).sign();
}

/// Step (d): the solutions of p(u, v) = o + s d with (u, v) in (0, 1)^2 and s > 0, with
/// multiplicity and by orientation. Precondition: steps (a) to (c) did not apply.
///
/// With t = u v, u e + v f + t g - s d = o - p00 is linear in (u, v, t, s). When its
/// matrix has rank 3 the solutions form a line, and the roots of the surface condition
/// t = u v along that line are exactly the solutions (u, v, s), the multiplicity of a
/// root being that of the solution. A double root is a ray tangent to the patch or
/// through the fold of a flat patch: n . d = 0 there (checked), and it counts 0 by
/// orientation.
CrossingCounts count_crossings(const ExactPatch& patch, const Vec3& o, const Vec3& d) {
  const std::optional<AffineSet> set =
      solve(from_columns({patch.e(), patch.f(), patch.g(), Rational(-1) * d}), o - patch.p00);
  if (!set) return {};
  if (set->directions.size() != 1) {
    // Rank <= 2: the corners and d span at most a plane, which contains o - p00 as the
    // system is consistent, so the corners and the whole ray lie in one plane. Step (c)
    // did not apply, so the ray misses the corners' hull, which contains the patch.
    if (ray_meets_hull(o, d, patch.corners(), RayStart::open)) {
      throw std::logic_error("ray_patch_oracle: in-plane ray meets the hull uncaught");
    }
    return {};
  }
  const AffineSet& line = *set;
  const Quadratic q = surface_condition_on_line(line);
  if (q.is_zero()) {
    // The ray's line lies in the surface; a solution arc inside the open square with s > 0
    // would run to the square's boundary with s > 0 (step b) or reach s = 0 (step a).
    std::vector<Inequality> domain = unit_square_constraints(line, Square::open);
    domain.push_back({coordinate(line, kS), true});
    if (is_feasible(std::move(domain))) {
      throw std::logic_error("ray_patch_oracle: infinitely many crossings uncaught");
    }
    return {};
  }
  CrossingCounts counts;
  for (const Root& root : real_roots(q)) {
    const QuadraticSurd u = coordinate_at(line, kU, root.value);
    const QuadraticSurd v = coordinate_at(line, kV, root.value);
    if (in_unit_interval(u, Square::open) && in_unit_interval(v, Square::open) &&
        coordinate_at(line, kS, root.value).sign() == Sign::positive) {
      counts.with_multiplicity += root.multiplicity;
      const Sign orientation = normal_dot_direction(patch, d, u, v);
      if (root.multiplicity == 1) {
        if (orientation == Sign::zero) {
          throw std::logic_error("ray_patch_oracle: a simple crossing where n . d = 0");
        }
        counts.signed_count += to_int(orientation);
      } else if (orientation != Sign::zero) {
        throw std::logic_error("ray_patch_oracle: a double crossing where n . d != 0");
      }
    }
  }
  return counts;
}

Vec3 exact_direction(const Vector3& direction) {
  Vec3 d = exact(direction);
  if (is_zero(d)) throw std::invalid_argument("rational oracle: zero ray direction");
  return d;
}

// ---------------------------------------------------------------------------------------
// Ray and triangle.

/// The line of the ray crosses the triangle's plane at a single point (n . d != 0).
RayTriangleHit ray_triangle_transversal(const Vec3& o, const Vec3& d,
                                        const std::array<Vec3, 3>& abc, const Vec3& n) {
  const Vec3& a = abc[0];
  const Rational s = dot(n, a - o) / dot(n, d);
  if (s < 0) return {};
  const Vec3 x = o + s * d;
  // x - a = beta (b - a) + gamma (c - a); crossing with (c - a), resp. (b - a), isolates
  // beta n, resp. gamma n.
  const Vec3 ab = abc[1] - a;
  const Vec3 ac = abc[2] - a;
  const Rational nn = dot(n, n);
  const Rational beta = dot(n, cross(x - a, ac)) / nn;
  const Rational gamma = dot(n, cross(ab, x - a)) / nn;
  const std::array<Rational, 3> weights{1 - beta - gamma, beta, gamma};  // of a, b, c
  if (std::any_of(weights.begin(), weights.end(), [](const Rational& w) { return w < 0; })) {
    return {};
  }
  if (s == 0) return {RayTriangle::origin_on, 0, Sign::zero};
  const Sign turn = sign_of(dot(n, d));
  std::vector<std::size_t> zero, nonzero;
  for (std::size_t i = 0; i < 3; ++i) {
    (weights[i] == 0 ? zero : nonzero).push_back(i);
  }
  if (zero.empty()) return {RayTriangle::interior, 0, turn};
  if (zero.size() == 1) {
    // The edge opposite the vertex of zero weight: c -> ab (0), a -> bc (1), b -> ca (2).
    return {RayTriangle::edge, static_cast<std::uint8_t>((zero.front() + 1) % 3), turn};
  }
  return {RayTriangle::vertex, static_cast<std::uint8_t>(nonzero.front()), turn};
}

}  // namespace

Sign orient3d_oracle(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const Vec3 qa = exact(a);
  return sign_of(det(exact(b) - qa, exact(c) - qa, exact(d) - qa));
}

RayTriangleHit ray_triangle_oracle(const Point3& origin, const Vector3& direction, const Point3& a,
                                   const Point3& b, const Point3& c) {
  const Vec3 o = exact(origin);
  const Vec3 d = exact_direction(direction);
  const std::array<Vec3, 3> abc{exact(a), exact(b), exact(c)};
  const Vec3 n = cross(abc[1] - abc[0], abc[2] - abc[0]);
  if (dot(n, d) != 0) return ray_triangle_transversal(o, d, abc, n);
  // Ray parallel to the plane, or zero-area triangle.
  const std::vector<Vec3> hull{abc[0], abc[1], abc[2]};
  if (hull_contains(hull, o)) return {RayTriangle::origin_on, 0, Sign::zero};
  if (ray_meets_hull(o, d, hull, RayStart::closed)) return {RayTriangle::coplanar, 0, Sign::zero};
  return {};
}

RayPatch ray_patch_oracle(const Point3& origin, const Vector3& direction,
                          const BilinearPatch& patch) {
  const ExactPatch p = exact(patch);
  const Vec3 o = exact(origin);
  const Vec3 d = exact_direction(direction);
  if (const std::optional<RayPatch> decided = decide_without_counting(p, o, d)) return *decided;
  return count_crossings(p, o, d).with_multiplicity % 2 == 1 ? RayPatch::odd : RayPatch::even;
}

int ray_patch_crossings_oracle(const Point3& origin, const Vector3& direction,
                               const BilinearPatch& patch) {
  const ExactPatch p = exact(patch);
  const Vec3 o = exact(origin);
  const Vec3 d = exact_direction(direction);
  if (decide_without_counting(p, o, d)) {
    throw std::invalid_argument("ray_patch_crossings_oracle: origin on patch or degenerate ray");
  }
  return count_crossings(p, o, d).with_multiplicity;
}

RayPatchCrossings ray_patch_signed_crossings_oracle(const Point3& origin, const Vector3& direction,
                                                    const BilinearPatch& patch) {
  const ExactPatch p = exact(patch);
  const Vec3 o = exact(origin);
  const Vec3 d = exact_direction(direction);
  if (const std::optional<RayPatch> decided = decide_without_counting(p, o, d)) {
    return {*decided, Sign::zero};
  }
  const CrossingCounts counts = count_crossings(p, o, d);
  if (counts.signed_count < -1 || counts.signed_count > 1) {
    throw std::domain_error("ray_patch_signed_crossings_oracle: signed count " +
                            std::to_string(counts.signed_count) + ", outside -1..1");
  }
  return {counts.with_multiplicity % 2 == 1 ? RayPatch::odd : RayPatch::even,
          static_cast<Sign>(counts.signed_count)};
}

bool point_on_patch_oracle(const Point3& x, const BilinearPatch& patch) {
  return on_patch(exact(patch), exact(x));
}

PatchShape patch_shape_oracle(const BilinearPatch& patch) {
  const std::vector<Vec3> c = exact(patch).corners();
  const Vec3 d1 = c[1] - c[0];
  const Vec3 d2 = c[2] - c[0];
  const Vec3 d3 = c[3] - c[0];
  switch (rank(from_rows({d1, d2, d3}))) {
    case 0:
      return PatchShape::point;
    case 1:
      return PatchShape::segment;
    case 3:
      return PatchShape::skew;
    default:
      break;
  }
  // Planar: measure turns along a nonzero normal of the plane.
  Vec3 normal = cross(d1, d2);
  if (is_zero(normal)) normal = cross(d1, d3);
  if (is_zero(normal)) normal = cross(d2, d3);
  std::array<Sign, 4> turns{};
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec3& previous = c[(i + 3) % 4];
    const Vec3& next = c[(i + 1) % 4];
    turns[i] = sign_of(dot(normal, cross(c[i] - previous, next - c[i])));
  }
  if (std::find(turns.begin(), turns.end(), Sign::zero) != turns.end()) {
    return PatchShape::degenerate_planar;
  }
  if (segments_intersect(c[0], c[1], c[2], c[3]) || segments_intersect(c[1], c[2], c[3], c[0])) {
    return PatchShape::butterfly;
  }
  const bool all_equal =
      std::all_of(turns.begin(), turns.end(), [&](Sign turn) { return turn == turns.front(); });
  return all_equal ? PatchShape::convex : PatchShape::concave;
}

Sign patch_side_oracle(const BilinearPatch& patch, const Point3& x) {
  const ExactPatch p = exact(patch);
  const Vec3 e = p.e();
  const Vec3 f = p.f();
  const Vec3 g = p.g();
  const Rational volume = det(e, f, g);
  if (volume == 0) throw std::invalid_argument("patch_side_oracle: flat patch");
  // x - p00 = alpha e + beta f + gamma g (Cramer: alpha = det[w, f, g] / volume, ...), and
  // the quadric is gamma = alpha beta. phi = volume^2 (gamma - alpha beta) is negative at
  // the midpoint (e + f) / 2 of the diagonal p10 - p01, where (alpha, beta, gamma) =
  // (1/2, 1/2, 0).
  const Vec3 w = exact(x) - p.p00;
  const Rational phi = volume * det(e, f, w) - det(w, f, g) * det(e, w, g);
  return sign_of(phi);
}

}  // namespace exactgeo::testing
