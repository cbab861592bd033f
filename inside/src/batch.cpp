#include "exactgeo/inside/batch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "exactgeo/boxes/morton.hpp"
#include "exactgeo/parallel/blocks.hpp"

namespace exactgeo::inside {
namespace {

/// Points a block holds: threads take blocks in turn (points differ in cost: re-casts,
/// candidate counts).
constexpr std::size_t kBlock = 512;

/// x's cell along one axis of [lower, upper]: the fraction of the way, in
/// 2^boxes::kMortonBits steps, clamped (a non-finite x, or an axis of no length, gives cell
/// 0). Halved first so that no difference overflows, whatever the points' magnitude.
std::uint32_t cell_of(double x, double lower, double upper) noexcept {
  constexpr double kCells = 1 << boxes::kMortonBits;
  const double extent = upper / 2 - lower / 2;
  const double fraction = (x / 2 - lower / 2) / extent;
  if (!(fraction > 0.0)) return 0;  // also NaN: a non-finite x or extent 0
  return static_cast<std::uint32_t>(std::min(fraction * kCells, kCells - 1));
}

/// The points' indices along a Morton (Z-order) curve through the box of their finite
/// coordinates, ties in input order (boxes/morton.hpp: a stable radix sort, a few
/// instructions a point where a comparison sort took about 200). Consecutive points are
/// then mostly close, which the boundary tree's carried first cut pays off on
/// (docs/inside.md, "Points in a spatial order"). Precondition: fewer than 2^32 points.
std::vector<std::uint32_t> spatial_order(std::span<const Point3> points) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Point3 lower{kInf, kInf, kInf}, upper{-kInf, -kInf, -kInf};
  for (const Point3& p : points) {
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(p[i])) continue;
      lower[i] = std::min(lower[i], p[i]);
      upper[i] = std::max(upper[i], p[i]);
    }
  }
  std::vector<std::uint64_t> keys(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    std::uint32_t code = 0;
    for (int i = 0; i < 3; ++i)
      code |= boxes::morton_spread(cell_of(points[k][i], lower[i], upper[i])) << i;
    keys[k] = std::uint64_t{code} << 32 | k;
  }
  boxes::sort_morton_keys(keys);
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t k = 0; k < keys.size(); ++k)
    order[k] = static_cast<std::uint32_t>(keys[k]);
  return order;
}

/// answers[order[i]] = classify_point(points[order[i]]) for every i (order empty: the
/// identity), in blocks of kBlock consecutive places of the order that threads take in
/// turn. Each thread works with its own copy of `classify_point`, which may therefore keep
/// scratch memory, and classifies each block's points in the order's sequence.
template <class Answer, class ClassifyPoint>
void classify_in_blocks(std::span<const Point3> points, std::span<Answer> locations,
                        unsigned threads, const ClassifyPoint& classify_point,
                        std::span<const std::uint32_t> order = {}) {
  if (locations.size() != points.size()) {
    throw std::invalid_argument("classify_batch: as many answers as points are needed");
  }
  const std::size_t blocks = (points.size() + kBlock - 1) / kBlock;
  parallel::for_each_block(
      blocks, threads,
      [&points, &locations, order, classify = classify_point](std::size_t b) mutable {
        const std::size_t end = std::min(points.size(), (b + 1) * kBlock);
        for (std::size_t k = b * kBlock; k < end; ++k) {
          const std::size_t i = order.empty() ? k : order[k];
          locations[i] = classify(points[i]);
        }
      });
}

/// Whether classify_batch visits the points in spatial order: where the boundary tree's
/// term labels them (an open surface, a certified arithmetic) and has enough edges for the
/// work carried from one point to the next to pay for the sort (docs/inside.md, "Points in
/// a spatial order"); a closed surface's points, or a small boundary's, gain nothing from
/// it.
bool spatially_ordered(const Classifier& classifier, std::span<const Point3> points,
                       Arithmetic arithmetic) noexcept {
  return classifier.open() && classifier.boundary().size() >= kSpatialOrderEdges &&
         arithmetic != Arithmetic::plain_double && points.size() > 2 &&
         points.size() <= std::numeric_limits<std::uint32_t>::max();
}

}  // namespace

void classify_batch(const Classifier& classifier, std::span<const Point3> points,
                    std::span<Location> locations, Arithmetic arithmetic, unsigned threads) {
  std::vector<std::uint32_t> order;
  ClassifierScratch scratch;
  if (spatially_ordered(classifier, points, arithmetic)) {
    order = spatial_order(points);
    // The point before is a neighbour: its first cut fits, and may go finer.
    scratch.boundary.finest_first_cut = kBoundaryTreeSpatialFirstCut;
  }
  classify_in_blocks(
      points, locations, threads,
      [&classifier, arithmetic, scratch](const Point3& point) mutable {
        return classifier.classify(point, arithmetic, scratch);
      },
      order);
}

void winding_number_batch(const Classifier& classifier, std::span<const Point3> points,
                          std::span<std::optional<std::int64_t>> windings, Arithmetic arithmetic,
                          unsigned threads) {
  classify_in_blocks(
      points, windings, threads,
      [&classifier, arithmetic, scratch = ClassifierScratch{}](const Point3& point) mutable {
        return classifier.winding_number(point, arithmetic, scratch);
      });
}

void generalized_winding_number_batch(const Classifier& classifier, std::span<const Point3> points,
                                      std::span<std::optional<Enclosure>> windings,
                                      Arithmetic arithmetic, unsigned threads) {
  classify_in_blocks(
      points, windings, threads,
      [&classifier, arithmetic, scratch = ClassifierScratch{}](const Point3& point) mutable {
        return classifier.generalized_winding_number(point, arithmetic, scratch);
      });
}

void classify_batch(const FloatRayParity& baseline, std::span<const Point3> points,
                    std::span<Location> locations, unsigned threads) {
  classify_in_blocks(points, locations, threads,
                     [&baseline](const Point3& point) { return baseline.classify(point); });
}

}  // namespace exactgeo::inside
