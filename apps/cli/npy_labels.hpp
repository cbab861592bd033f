#pragma once

// Labels as a NumPy .npy file: a one-dimensional int8 array in input order, the codes of
// the Python module (exactgeo.OUTSIDE, INSIDE, BOUNDARY, UNDECIDED: inside::Location's
// values), which is what `exactgeo.dask.classify_meshes` writes for each mesh.

#include <span>
#include <string>

#include "exactgeo/inside/location.hpp"

namespace exactgeo::cli {

/// The .npy file's bytes for these labels.
std::string npy_labels(std::span<const inside::Location> labels);

}  // namespace exactgeo::cli
