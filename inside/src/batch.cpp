#include "exactgeo/inside/batch.hpp"

#include <algorithm>
#include <stdexcept>

#include "exactgeo/parallel/blocks.hpp"

namespace exactgeo::inside {
namespace {

/// answers[i] = classify_point(points[i]) for every i, in blocks of 512 points that
/// threads take in turn (points differ in cost: re-casts, candidate counts). Each thread
/// works with its own copy of `classify_point`, which may therefore keep scratch memory.
template <class Answer, class ClassifyPoint>
void classify_in_blocks(std::span<const Point3> points, std::span<Answer> locations,
                        unsigned threads, const ClassifyPoint& classify_point) {
  if (locations.size() != points.size()) {
    throw std::invalid_argument("classify_batch: as many answers as points are needed");
  }
  constexpr std::size_t kBlock = 512;
  const std::size_t blocks = (points.size() + kBlock - 1) / kBlock;
  parallel::for_each_block(blocks, threads,
                           [&points, &locations, classify = classify_point](std::size_t b) mutable {
                             const std::size_t end = std::min(points.size(), (b + 1) * kBlock);
                             for (std::size_t i = b * kBlock; i < end; ++i) {
                               locations[i] = classify(points[i]);
                             }
                           });
}

}  // namespace

void classify_batch(const Classifier& classifier, std::span<const Point3> points,
                    std::span<Location> locations, Arithmetic arithmetic, unsigned threads) {
  classify_in_blocks(
      points, locations, threads,
      [&classifier, arithmetic, scratch = ClassifierScratch{}](const Point3& point) mutable {
        return classifier.classify(point, arithmetic, scratch);
      });
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
