#include "exactgeo/inside/batch.hpp"

#include <algorithm>
#include <stdexcept>

#include "exactgeo/parallel/blocks.hpp"

namespace exactgeo::inside {

void classify_batch(const Classifier& classifier, std::span<const Point3> points,
                    std::span<Location> locations, Arithmetic arithmetic, unsigned threads) {
  if (locations.size() != points.size()) {
    throw std::invalid_argument("classify_batch: as many locations as points are needed");
  }
  // Points differ in cost (re-casts, candidate counts): workers take blocks in turn.
  constexpr std::size_t kBlock = 512;
  const std::size_t blocks = (points.size() + kBlock - 1) / kBlock;
  parallel::for_each_block(blocks, threads,
                           [&, scratch = ClassifierScratch{}](std::size_t b) mutable {
                             const std::size_t end = std::min(points.size(), (b + 1) * kBlock);
                             for (std::size_t i = b * kBlock; i < end; ++i) {
                               locations[i] = classifier.classify(points[i], arithmetic, scratch);
                             }
                           });
}

}  // namespace exactgeo::inside
