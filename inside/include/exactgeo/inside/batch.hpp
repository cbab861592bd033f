#pragma once

// Classifying many points at once, on all cores. The output depends only on the input:
// locations[i] is the location of points[i], whatever the thread count or schedule.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/float_ray_parity.hpp"
#include "exactgeo/inside/location.hpp"

namespace exactgeo::inside {

/// The fewest boundary edges an open surface has for classify_batch to visit the points in
/// a spatial order (docs/inside.md, "Points in a spatial order"): with fewer, the boundary
/// tree's term costs too little for the order to pay for its sort. A cost only: the
/// labels are the same in any order.
inline constexpr std::size_t kSpatialOrderEdges = 1024;

/// Writes classify(points[i]) into locations[i] for every i, using `threads` threads
/// (0: one per hardware thread). Against an open surface of at least kSpatialOrderEdges
/// boundary edges, in the certified arithmetics, the points are visited along a Morton
/// curve (each thread taking runs of consecutive points of it); the labels are the same.
/// Precondition: locations.size() == points.size().
/// Rethrows the first exception a worker threw (only std::bad_alloc is possible).
void classify_batch(const Classifier& classifier, std::span<const Point3> points,
                    std::span<Location> locations, Arithmetic arithmetic, unsigned threads = 0);

/// Writes winding_number(points[i]) into windings[i] (nullopt: on the surface) for every
/// i, the same way. Rethrows winding_number's std::logic_error when the classifier's mesh
/// has no winding numbers (Classifier::oriented).
void winding_number_batch(const Classifier& classifier, std::span<const Point3> points,
                          std::span<std::optional<std::int64_t>> windings, Arithmetic arithmetic,
                          unsigned threads = 0);

/// Writes generalized_winding_number(points[i]) into windings[i] (nullopt: on the
/// surface) for every i, the same way; rethrows its std::logic_error likewise.
void generalized_winding_number_batch(const Classifier& classifier, std::span<const Point3> points,
                                      std::span<std::optional<Enclosure>> windings,
                                      Arithmetic arithmetic, unsigned threads = 0);

/// The same with the inexact float ray-casting baseline (float_ray_parity.hpp), for
/// measuring it against the exact classifier on the same points.
void classify_batch(const FloatRayParity& baseline, std::span<const Point3> points,
                    std::span<Location> locations, unsigned threads = 0);

}  // namespace exactgeo::inside
