#include "exactgeo/inside/batch.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace exactgeo::inside {

void classify_batch(const Classifier& classifier, std::span<const Point3> points,
                    std::span<Location> locations, Arithmetic arithmetic, unsigned threads) {
  if (locations.size() != points.size()) {
    throw std::invalid_argument("classify_batch: as many locations as points are needed");
  }
  // Workers take blocks in turn: points differ in cost (recasts, candidate counts), so a
  // static split would leave threads idle. Block b always covers the same points.
  constexpr std::size_t kBlock = 512;
  const std::size_t blocks = (points.size() + kBlock - 1) / kBlock;
  std::atomic<std::size_t> next_block{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;

  const auto work = [&] {
    try {
      ClassifierScratch scratch;
      for (std::size_t b = next_block++; b < blocks; b = next_block++) {
        const std::size_t end = std::min(points.size(), (b + 1) * kBlock);
        for (std::size_t i = b * kBlock; i < end; ++i) {
          locations[i] = classifier.classify(points[i], arithmetic, scratch);
        }
      }
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next_block = blocks;
    }
  };

  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(blocks, 1)));
  std::vector<std::thread> workers;
  workers.reserve(threads - 1);
  for (unsigned t = 1; t < threads; ++t)
    workers.emplace_back(work);
  work();
  for (std::thread& w : workers)
    w.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace exactgeo::inside
