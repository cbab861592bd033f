#pragma once

// Runs numbered blocks of work on a few threads, each block exactly once. Workers take
// blocks in turn (blocks differ in cost, so a static split would leave threads idle);
// what a block computes depends only on its number, so results stored per block are the
// same for every thread count. Used by the batch entry points of ccd/ and inside/.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace exactgeo::parallel {

/// The thread count to use: `requested`, or one per hardware thread when 0, and never more
/// than there are blocks.
inline unsigned worker_count(unsigned requested, std::size_t blocks) noexcept {
  unsigned threads = requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(blocks, 1)));
}

/// Calls work(b) for every b in [0, blocks). Each thread runs its own copy of `work`, so a
/// mutable lambda can keep per-thread scratch. The first exception stops the other
/// workers after their current block and is rethrown here.
template <class Work>
void for_each_block(std::size_t blocks, unsigned threads, const Work& work) {
  std::atomic<std::size_t> next_block{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto run = [&] {
    try {
      Work mine = work;
      for (std::size_t b = next_block++; b < blocks; b = next_block++)
        mine(b);
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next_block = blocks;
    }
  };
  threads = worker_count(threads, blocks);
  std::vector<std::thread> workers;
  workers.reserve(threads - 1);
  for (unsigned t = 1; t < threads; ++t)
    workers.emplace_back(run);
  run();
  for (std::thread& w : workers)
    w.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace exactgeo::parallel
