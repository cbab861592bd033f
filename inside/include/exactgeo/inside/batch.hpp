#pragma once

// Classifying many points at once, on all cores. The output depends only on the input:
// locations[i] is the location of points[i], whatever the thread count or schedule.

#include <span>

#include "exactgeo/inside/classifier.hpp"

namespace exactgeo::inside {

/// Writes classify(points[i]) into locations[i] for every i, using `threads` threads
/// (0: one per hardware thread). Precondition: locations.size() == points.size().
/// Rethrows the first exception a worker threw (only std::bad_alloc is possible).
void classify_batch(const Classifier& classifier, std::span<const Point3> points,
                    std::span<Location> locations, Arithmetic arithmetic, unsigned threads = 0);

}  // namespace exactgeo::inside
