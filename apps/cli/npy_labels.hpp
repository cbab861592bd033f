#pragma once

// Labels as a NumPy .npy file: a one-dimensional int8 array in input order, the codes of
// the Python module (exactgeo.OUTSIDE, INSIDE, BOUNDARY, UNDECIDED: inside::Location's
// values), which is what `exactgeo.dask.classify_meshes` writes for each mesh.

#include <optional>
#include <string>
#include <string_view>

namespace exactgeo::cli {

/// The .npy file's bytes for labels given as text, one word a line (what `exactgeo
/// inside` prints); nullopt when a line is not a label.
std::optional<std::string> npy_labels(std::string_view text);

}  // namespace exactgeo::cli
